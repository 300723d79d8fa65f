// What Python holds of a client: shared, so a telemetry subscription keeps
// the client's DDS participant alive while it still reads, and closable, so
// Python decides when the client's threads end (not the garbage collector).
#pragma once

#include <memory>

#include "dem/client/client.h"

namespace dem::python {

struct ClientHandle {
  std::shared_ptr<client::Client> client;

  // The client; std::runtime_error once closed.
  client::Client& get() const;
};

}  // namespace dem::python
