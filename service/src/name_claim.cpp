#include "dem/service/name_claim.h"

#include <spdlog/spdlog.h>

#include <thread>

#include "dem/dds/discovery.h"
#include "dem/protocol/qos.h"
#include "dem/protocol/topics.h"

namespace dem::service {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::chrono::milliseconds kPoll{50};

// What the other participants of the domain have under the name.
struct Rivals {
  bool holder = false;            // a status writer: a server serving under the name
  bool earlier_claimant = false;  // a claim from a participant whose GUID is below ours
};

}  // namespace

NameClaim::NameClaim(const dds::Participant& participant, const std::string& name, std::chrono::milliseconds discovery,
                     std::chrono::milliseconds wait)
    : topic_(participant, protocol::topic_name(name, protocol::TopicKind::kNameClaim)),
      writer_(participant, topic_, protocol::status_qos()) {
  const dds::PublicationMonitor publications(participant);
  const dds::Guid self = dds::guid_of(participant);
  const std::string status_topic = protocol::topic_name(name, protocol::TopicKind::kStatus);
  const auto look = [&] {
    Rivals rivals;
    for (const dds::Publication& publication : publications.alive()) {
      if (publication.participant == self) continue;
      if (publication.topic_name == status_topic) rivals.holder = true;
      if (publication.topic_name == topic_.name() && publication.participant < self) rivals.earlier_claimant = true;
    }
    return rivals;
  };
  const std::string domain = std::to_string(participant.domain_id());

  std::this_thread::sleep_for(discovery);
  Rivals rivals = look();
  if (rivals.holder) {
    spdlog::warn(
        "a server named {} is on DDS domain {}: waiting up to {} s for it to leave (a server that died keeps "
        "its name until its lease runs out)",
        name, domain, std::chrono::duration<double>(wait).count());
    const auto deadline = Clock::now() + wait;
    while (rivals.holder && Clock::now() < deadline) {
      std::this_thread::sleep_for(kPoll);
      rivals = look();
    }
    if (rivals.holder) {
      throw NameInUse("a server named \"" + name + "\" is already on DDS domain " + domain +
                      ": choose another --name, or another --domain");
    }
  }
  // A contest: the claimant with the lowest GUID goes on; the others wait
  // for it to hold the name (a moment: it publishes its status next) or to
  // leave. One that holds the name now was claiming a moment ago, alive:
  // no lease to wait for.
  const auto deadline = Clock::now() + wait;
  while (rivals.earlier_claimant) {
    if (rivals.holder || Clock::now() >= deadline) {
      throw NameInUse("another server named \"" + name + "\" started on DDS domain " + domain +
                      " at the same time and takes the name (of servers started together, the one whose DDS "
                      "participant has the lowest GUID does): choose another --name, or another --domain");
    }
    std::this_thread::sleep_for(kPoll);
    rivals = look();
  }
}

}  // namespace dem::service
