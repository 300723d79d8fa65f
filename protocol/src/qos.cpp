#include "dem/protocol/qos.h"

#include <chrono>

namespace dem::protocol {

using namespace std::chrono_literals;

// A client's command write waits at most a second for room; it never needs to.
dds::Qos command_qos() { return dds::Qos().reliable(1s).keep_all().volatile_durability(); }

// Replies are written by the server's threads, and every client's reader
// matches the topic. Keeping all of them until every reader acknowledged
// would let one client that stops reading (a process stopped in a
// debugger, SIGSTOP) block every write - every other client's replies and
// the engine with them: Cyclone 0.10 has no resource limits for a
// writer's history, and it never drops an unresponsive reader, so KEEP_ALL
// would throttle the writer until its max blocking time and then fail
// every write. So the writer keeps the last 256 - of each client: the
// reply is keyed by client_id (idl/dem/command.idl), and keep-last counts
// per key. Each client has at most 64 requests unanswered
// (client::ConnectOptions::max_outstanding), so no reply of its leaves the
// history before it was delivered, however far its process falls behind
// and however many replies other clients get meanwhile (before the key,
// the 256 were for all clients together, and bench_responsiveness --flood
// lost 64 to 102 of some 100,000 in 3 of 8 runs; docs/RELIABILITY.md). A
// stalled reader holds at most 256 replies of each client in the server's
// memory, and loses only what it was not reading; a repair of a lost
// packet comes from this history. The ReplySender paces a reply of many
// chunks (reply_sender.cpp).
constexpr int kReplyHistory = 256;
dds::Qos reply_qos() { return dds::Qos().reliable(5s).keep_last(kReplyHistory).volatile_durability(); }

// Keeps all it receives: a client's own replies alone, the others' are
// turned away unread by its instance filter (dds::OwnInstanceFilter).
dds::Qos reply_reader_qos() { return dds::Qos().reliable(5s).keep_all().volatile_durability(); }

// The current state, replayed to late joiners: one sample, durable.
dds::Qos status_qos() { return dds::Qos().reliable(0ns).keep_last(1).transient_local(); }

// Telemetry is a run's recent history, as a ROS 2 latched topic with a
// depth: the writer keeps its last 256 samples and hands them to a reader
// that joins later (transient-local), so a monitor, a recording or a
// dashboard started beside a run begins at its start - at the telemetry
// interval the demo uses, 256 samples are 256,000 cycles - or, on a long
// run, at its last 256 samples. Keep-last, so a write never waits for a
// reader: a stalled one holds at most the 256 samples (a few hundred kB at
// most) and costs the others nothing (DDS.md).
constexpr int kTelemetryHistory = 256;
dds::Qos telemetry_writer_qos() {
  return dds::Qos().reliable(0ns).keep_last(kTelemetryHistory).transient_local(kTelemetryHistory);
}

// Transient-local to be given the writer's history; a reader's own 1024
// samples leave room for a monitor that falls behind for a while.
dds::Qos telemetry_reader_qos() { return dds::Qos().reliable(1s).keep_last(1024).transient_local(); }

}  // namespace dem::protocol
