// A load that takes long - here a random packing close to jamming - does
// not hold the server: get_state is answered while it prepares, stop
// abandons it at once, and one that outlasts the time limit is refused,
// the world left as it was; the abandoned packing itself stops too
// (service/include/dem/service/background_load.h).
#include <gtest/gtest.h>

#include "dem/service/background_load.h"
#include "service_test_support.h"

namespace dem::test {
namespace {

using protocol::CommandKind;
using protocol::ReplyStatus;

std::uint64_t start_slow_load(client::Client& client) {
  protocol::Command load;
  load.kind = static_cast<std::uint8_t>(CommandKind::kLoadCase);
  load.load_case.text = read_text(std::filesystem::path(DEM_SERVICE_TEST_DATA) / "slow_packing.case.txtpb");
  return client.send(load);
}

// An abandoned packing is told to stop and ends within a few thousand
// attempts, where it would have run on for seconds (the case takes some
// 2.6 s, and is abandoned after 0.3).
void wait_for_abandoned_loads() {
  ASSERT_TRUE(eventually([] { return service::BackgroundLoad::running() == 0; }, 1s));
}

TEST(Loading, GetStateIsAnsweredAndStopAbandonsALongLoad) {
  service::ServerOptions options = server_options("loading", kLoadingStop);
  InProcessServer server(options);
  client::Client client(connect_options("loading", kLoadingStop));
  client.load_case_file(case_file("nine_disc_damped"));
  const std::uint64_t hash = client.get_state().state_hash;

  const std::uint64_t load = start_slow_load(client);
  std::this_thread::sleep_for(300ms);
  // Another client: this one's get_state would wait for its own load (a
  // client always sees its earlier commands done).
  client::Client watcher(connect_options("loading", kLoadingStop));
  const protocol::Reply during = watcher.get_state();
  EXPECT_LT(during.duration, 0.05);  // answered while the packing is placed
  EXPECT_EQ(during.state.case_name, "nine_disc_damped");
  const auto stop_sent = std::chrono::steady_clock::now();
  const protocol::Reply stopped = client.stop();
  EXPECT_EQ(stopped.message, "stopped the load_case in preparation");
  const std::optional<protocol::Reply> cancelled = client.await(load, 10s);
  ASSERT_TRUE(cancelled);
  EXPECT_LT(std::chrono::steady_clock::now() - stop_sent, 2s);
  EXPECT_EQ(cancelled->status, ReplyStatus::kCancelled);
  EXPECT_EQ(cancelled->message, "load_case stopped by request before it was ready");
  EXPECT_EQ(client.get_state().state_hash, hash);  // nothing half-applied
  wait_for_abandoned_loads();
}

TEST(Loading, ALoadOutlastingItsTimeLimitIsRefused) {
  service::ServerOptions options = server_options("limited", kLoadingTimeLimit);
  options.load_time_limit = 300ms;
  InProcessServer server(options);
  client::Client client(connect_options("limited", kLoadingTimeLimit));
  client.load_case_file(case_file("nine_disc_damped"));
  const std::optional<protocol::Reply> failed = client.await(start_slow_load(client), 20s);
  ASSERT_TRUE(failed);
  EXPECT_EQ(failed->status, ReplyStatus::kFailed);
  EXPECT_EQ(failed->message,
            "load_case: preparing it took more than 0.3 s (--load-seconds); is there a random "
            "packing that nearly cannot fit?");
  EXPECT_EQ(client.get_state().state.case_name, "nine_disc_damped");
  wait_for_abandoned_loads();
  // Once it has ended, loads work again (while it ends, another is answered busy).
  EXPECT_TRUE(client.load_case_file(case_file("nine_disc_damped")).ok());
}

}  // namespace
}  // namespace dem::test
