#include "dem/service/name_claim.h"

#include <spdlog/spdlog.h>

#include <thread>

#include "dem/dds/discovery.h"
#include "dem/protocol/topics.h"

namespace dem::service {

void claim_name(const dds::Participant& participant, const std::string& name, std::uint32_t domain,
                std::chrono::milliseconds discovery, std::chrono::milliseconds wait) {
  const dds::PublicationMonitor publications(participant);
  const std::string status_topic = protocol::topic_name(name, protocol::TopicKind::kStatus);
  const auto taken = [&] {
    for (const dds::Publication& publication : publications.alive()) {
      if (publication.topic_name == status_topic) return true;
    }
    return false;
  };
  std::this_thread::sleep_for(discovery);
  if (!taken()) return;
  spdlog::warn("a server named {} is on DDS domain {}: waiting up to {} s for it to leave (a server that died keeps "
               "its name until its lease runs out)",
               name, domain, std::chrono::duration<double>(wait).count());
  const auto deadline = std::chrono::steady_clock::now() + wait;
  while (std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    if (!taken()) return;
  }
  throw NameInUse("a server named \"" + name + "\" is already on DDS domain " + std::to_string(domain) +
                  ": choose another --name, or another --domain");
}

}  // namespace dem::service
