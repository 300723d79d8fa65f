#include "dem/protocol/qos.h"

#include <chrono>

namespace dem::protocol {

using namespace std::chrono_literals;

// A client's command write waits at most a second for room; it never needs to.
dds::Qos command_qos() { return dds::Qos().reliable(1s).keep_all().volatile_durability(); }

// Replies are written by the server's engine thread. A large reply (contacts,
// a snapshot) is flow-controlled by acknowledgements, so a write may wait
// for a client to catch up - but never longer than this before the reply is
// given up (a client that stops reading mid-transfer).
dds::Qos reply_qos() { return dds::Qos().reliable(5s).keep_all().volatile_durability(); }

// The current state, replayed to late joiners: one sample, durable.
dds::Qos status_qos() { return dds::Qos().reliable(0ns).keep_last(1).transient_local(); }

dds::Qos telemetry_writer_qos() { return dds::Qos().reliable(0ns).keep_last(16).volatile_durability(); }

dds::Qos telemetry_reader_qos() { return dds::Qos().reliable(1s).keep_last(1024).volatile_durability(); }

}  // namespace dem::protocol
