// A reader that keeps one instance of a keyed topic: its own (a client's
// replies on a topic keyed by client). Set on a topic before a reader is
// made from it, the filter turns away the other instances' samples as they
// arrive, on their sample info alone - undecoded, never stored - once the
// reader has learnt which instance is its own from a sample it took (the
// instance handle Cyclone gives a key). Until then, and for samples of a
// writer it has not learnt its instance from (a restarted server), it lets
// all through, so the reader can learn.
#pragma once

#include <dds/dds.h>

#include <atomic>
#include <map>
#include <mutex>

namespace dem::dds {

class OwnInstanceFilter {
 public:
  // Filters the samples of `topic`'s readers; lives as long as they do.
  explicit OwnInstanceFilter(dds_entity_t topic);
  ~OwnInstanceFilter();
  OwnInstanceFilter(const OwnInstanceFilter&) = delete;
  OwnInstanceFilter& operator=(const OwnInstanceFilter&) = delete;

  // A sample taken from the reader was of its own instance.
  void learn(dds_instance_handle_t writer, dds_instance_handle_t instance);

  // Whether a sample of `instance` from `writer` is let through.
  bool accepts(dds_instance_handle_t writer, dds_instance_handle_t instance) const;

 private:
  dds_entity_t topic_;
  std::atomic<bool> published_{false};  // set before the filter is handed to Cyclone
  mutable std::mutex mutex_;
  // Each writer's handle in this participant with the reader's own
  // instance's handle. Cyclone gives a writer a new handle when it is
  // discovered again, and keeps an instance's handle while a writer has
  // it registered (the server's writer never unregisters one).
  std::map<dds_instance_handle_t, dds_instance_handle_t> own_;
};

}  // namespace dem::dds
