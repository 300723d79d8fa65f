// Discovery watched for peers whose interface does not meet this process's
// (interface_check.h): each writer or reader of another participant on the
// topics of one server is judged once, when discovery finds it, and
// reported unless it is of the same form. The server logs what it reports;
// a client reports it to its user (docs/DDS.md, "Evolving the wire").
#pragma once

#include <condition_variable>
#include <functional>
#include <mutex>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include "dem/dds/discovery.h"
#include "dem/protocol/interface_check.h"

namespace dem::protocol {

class InterfaceWatch {
 public:
  using Report = std::function<void(const PeerVerdict&)>;
  // `topic_prefix`: "rt/dem/<server>/"; `self`: "this server", "this client".
  // With `report`, a thread of its own checks discovery every 200 ms;
  // without, check() is called by the owner.
  InterfaceWatch(const dds::Participant& participant, std::string topic_prefix, std::string self, Report report = {});
  ~InterfaceWatch();
  InterfaceWatch(const InterfaceWatch&) = delete;
  InterfaceWatch& operator=(const InterfaceWatch&) = delete;

  // The verdicts on the endpoints found since the last check (none of the
  // same form), each endpoint once.
  std::vector<PeerVerdict> check();

 private:
  dds::Guid self_participant_;
  std::string topic_prefix_;
  std::string self_;
  dds::EndpointMonitor writers_;
  dds::EndpointMonitor readers_;
  std::mutex mutex_;
  std::set<std::string> judged_;
  std::condition_variable stop_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace dem::protocol
