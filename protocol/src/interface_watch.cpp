#include "dem/protocol/interface_watch.h"

#include <chrono>

namespace dem::protocol {

using namespace std::chrono_literals;

InterfaceWatch::InterfaceWatch(const dds::Participant& participant, std::string topic_prefix, std::string self,
                               Report report)
    : self_participant_(dds::guid_of(participant)),
      topic_prefix_(std::move(topic_prefix)),
      self_(std::move(self)),
      writers_(participant, dds::EndpointMonitor::Kind::kWriters),
      readers_(participant, dds::EndpointMonitor::Kind::kReaders) {
  if (!report) return;
  thread_ = std::thread([this, report = std::move(report)] {
    for (;;) {
      for (const PeerVerdict& verdict : check()) report(verdict);
      std::unique_lock lock(mutex_);
      if (stop_.wait_for(lock, 200ms, [this] { return stopping_; })) return;
    }
  });
}

InterfaceWatch::~InterfaceWatch() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  stop_.notify_all();
  if (thread_.joinable()) thread_.join();
}

std::vector<PeerVerdict> InterfaceWatch::check() {
  std::vector<dds::Endpoint> endpoints = writers_.alive();
  for (dds::Endpoint& reader : readers_.alive()) endpoints.push_back(std::move(reader));
  std::vector<PeerVerdict> verdicts;
  std::lock_guard lock(mutex_);
  for (const dds::Endpoint& endpoint : endpoints) {
    if (endpoint.participant == self_participant_ || !endpoint.topic_name.starts_with(topic_prefix_)) continue;
    // An endpoint is judged once; the same one declaring another hash is another.
    std::string key(endpoint.participant.begin(), endpoint.participant.end());
    key += endpoint.topic_name + (endpoint.writer ? "/w/" : "/r/") + endpoint.user_data;
    if (!judged_.insert(key).second) continue;
    PeerVerdict verdict = judge_peer(endpoint, self_);
    if (verdict.kind != PeerVerdict::Kind::kSame && verdict.kind != PeerVerdict::Kind::kNotOurs) {
      verdicts.push_back(std::move(verdict));
    }
  }
  return verdicts;
}

}  // namespace dem::protocol
