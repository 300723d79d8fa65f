// The QoS of each topic, chosen on purpose (docs/DDS.md explains why):
//   command, reply     reliable, keep all, volatile: nothing is lost, nothing replayed
//   status             reliable, transient-local, keep last 1: a late joiner sees the state now
//   plate_forces,      reliable, keep last 256, transient-local: a late joiner gets the
//   contact_stats,     recent history; the server's writes never block (max blocking
//   region_measures    time 0): a stalled subscriber costs samples, not cycles
#pragma once

#include "dem/dds/qos.h"

namespace dem::protocol {

dds::Qos command_qos();
dds::Qos reply_qos();
// A client keeps every reply it received until its thread takes it: a
// burst never overwrites one in the reader (docs/RELIABILITY.md).
dds::Qos reply_reader_qos();
dds::Qos status_qos();
dds::Qos telemetry_writer_qos();
// Readers keep a generous history so a monitor that falls behind for a
// while loses nothing, without ever holding the server up.
dds::Qos telemetry_reader_qos();

}  // namespace dem::protocol
