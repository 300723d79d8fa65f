// The pieces of the extension module dem._client, each bound in its own
// file and composed by module.cpp (as rclpy's _rclpy_pybind11 composes its
// parts over rcl).
#pragma once

#include <pybind11/pybind11.h>

namespace dem::python {

void bind_messages(pybind11::module_& module);   // Status, WallForce, PlateForces, ContactStats, Reply
void bind_errors(pybind11::module_& module);     // C++ client exceptions -> dem.errors
void bind_client(pybind11::module_& module);     // Client, list_servers
void bind_telemetry(pybind11::module_& module);  // Telemetry (a queue of samples)
void bind_tap(pybind11::module_& module);        // TelemetryTap (every server's telemetry as CDR bytes)

}  // namespace dem::python
