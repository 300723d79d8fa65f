// dem._client.TelemetryTap: every server's telemetry on a domain as CDR
// bytes (dem::client::TelemetryTap), for dem.bridge. take() waits with the
// GIL released, so a bridge's other threads (its web server) go on.
#include <pybind11/stl.h>

#include <chrono>
#include <memory>
#include <tuple>

#include "bindings.h"
#include "dem/client/telemetry_tap.h"

namespace dem::python {

namespace py = pybind11;

void bind_tap(py::module_& m) {
  py::class_<client::TelemetryTap>(m, "TelemetryTap",
                                   "Every server's telemetry on a DDS domain as CDR bytes (dem::client::TelemetryTap)")
      .def(py::init<std::uint32_t, const std::string&>(), py::arg("domain"), py::arg("dds_config") = "",
           py::call_guard<py::gil_scoped_release>())
      .def(
          "take",
          [](client::TelemetryTap& tap, double timeout) {
            std::vector<client::TapSample> samples;
            {
              py::gil_scoped_release release;
              samples = tap.take(std::chrono::milliseconds(static_cast<std::int64_t>(timeout * 1000.0)));
            }
            py::list result;
            for (const client::TapSample& s : samples) {
              result.append(py::make_tuple(s.server, s.topic, s.type, py::bytes(s.bytes), s.log_time, s.publish_time));
            }
            return result;
          },
          py::arg("timeout"),
          "Waits up to timeout seconds; [(server, topic, type, cdr bytes, log_time_ns, publish_time_ns)]")
      .def("servers", &client::TelemetryTap::servers, "The servers subscribed to now")
      .def_static(
          "topics",
          [](const std::string& server) {
            std::vector<std::pair<std::string, std::string>> topics;
            for (const client::TapTopic& t : client::TelemetryTap::topics(server)) topics.emplace_back(t.topic, t.type);
            return topics;
          },
          py::arg("server"), "[(topic, type)] a server publishes telemetry on");
}

}  // namespace dem::python
