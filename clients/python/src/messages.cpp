// The service's messages (protocol/include/dem/protocol/messages.h) as
// read-only Python objects. Vectors become (x, y, z) tuples, enumerations
// their names ("running", "not_found", "cycle"), byte strings bytes, and
// contacts a numpy structured array (contact_array.h).
#include <pybind11/stl.h>

#include <sstream>

#include "bindings.h"
#include "contact_array.h"
#include "dem/protocol/messages.h"

namespace dem::python {

namespace py = pybind11;
using namespace protocol;

namespace {

py::tuple tuple_of(const Vector3& v) { return py::make_tuple(v.x, v.y, v.z); }

double seconds_of(const Stamp& stamp) { return stamp.sec + 1e-9 * stamp.nanosec; }

std::string kind_name(std::uint8_t kind) {
  const auto known = command_kind(kind);
  return known ? std::string(to_string(*known)) : "unknown";
}

// Read-only vector members as tuples.
template <typename Class, typename Message>
void vector_property(Class& cls, const char* name, Vector3 Message::*member, const char* doc) {
  cls.def_property_readonly(name, [member](const Message& m) { return tuple_of(m.*member); }, doc);
}

}  // namespace

void bind_messages(py::module_& m) {
  register_contact_dtype();
  m.attr("CONTACT_DTYPE") = contact_dtype();

  py::class_<Status> status(m, "Status", "The server's status (durable topic rt/dem/<server>/status)");
  status.def_readonly("server", &Status::server)
      .def_property_readonly("state", [](const Status& s) { return std::string(to_string(s.state)); },
                             "idle, loaded, running, error or shutdown")
      .def_readonly("case_name", &Status::case_name)
      .def_readonly("dimension", &Status::dimension)
      .def_readonly("particles", &Status::particles)
      .def_readonly("walls", &Status::walls)
      .def_readonly("cycle", &Status::cycle)
      .def_readonly("time", &Status::time, "simulated time, s")
      .def_readonly("time_step", &Status::time_step, "s")
      .def_readonly("command", &Status::command, "the running command's kind, or empty")
      .def_readonly("command_client", &Status::command_client)
      .def_readonly("command_request_id", &Status::command_request_id)
      .def_readonly("command_cycles_done", &Status::command_cycles_done)
      .def_readonly("command_cycles_total", &Status::command_cycles_total)
      .def_readonly("progress", &Status::progress, "0 to 1")
      .def_readonly("message", &Status::message, "the last event")
      .def_readonly("commands_served", &Status::commands_served)
      .def_readonly("telemetry_dropped", &Status::telemetry_dropped)
      .def_property_readonly("stamp", [](const Status& s) { return seconds_of(s.stamp); }, "s since the Unix epoch")
      .def("__repr__", [](const Status& s) {
        std::ostringstream out;
        out << "<Status " << s.server << ": " << to_string(s.state) << ", case " << s.case_name << ", cycle "
            << s.cycle << ">";
        return out.str();
      });

  py::class_<WallForce> wall(m, "WallForce", "One wall's resultants, stress and settlement");
  wall.def_readonly("name", &WallForce::name).def_readonly("id", &WallForce::id);
  vector_property(wall, "force", &WallForce::force, "N (per unit depth in 2D)");
  vector_property(wall, "moment", &WallForce::moment, "about P, N m");
  wall.def_readonly("normal_force", &WallForce::normal_force, "N, compressive positive")
      .def_readonly("area", &WallForce::area, "m^2 (2D: length x unit depth)")
      .def_readonly("normal_stress", &WallForce::normal_stress, "normal force / area, Pa");
  vector_property(wall, "position", &WallForce::position, "of P, m");
  vector_property(wall, "displacement", &WallForce::displacement, "since the case was loaded, m");
  wall.def_readonly("settlement", &WallForce::settlement, "displacement along the normal towards the particles, m")
      .def_readonly("contacts", &WallForce::contacts)
      .def("__repr__", [](const WallForce& w) {
        std::ostringstream out;
        out << "<WallForce " << w.name << ": stress " << w.normal_stress << " Pa, settlement " << w.settlement
            << " m, " << w.contacts << " contacts>";
        return out.str();
      });

  py::class_<PlateForces>(m, "PlateForces", "Every wall's forces at one cycle (telemetry or a reply)")
      .def_readonly("server", &PlateForces::server)
      .def_readonly("cycle", &PlateForces::cycle)
      .def_readonly("time", &PlateForces::time, "simulated time, s")
      .def_property_readonly("stamp", [](const PlateForces& p) { return seconds_of(p.stamp); })
      .def_readonly("walls", &PlateForces::walls)
      .def(
          "wall",
          [](const PlateForces& p, const std::string& name) {
            for (const WallForce& w : p.walls) {
              if (w.name == name) return w;
            }
            std::string known;
            for (const WallForce& w : p.walls) known += (known.empty() ? "" : ", ") + w.name;
            throw py::key_error("no wall \"" + name + "\" (walls: " + known + ")");
          },
          py::arg("name"), "The wall of that name; KeyError naming the walls there are otherwise")
      .def("__repr__", [](const PlateForces& p) {
        return "<PlateForces of " + p.server + " at cycle " + std::to_string(p.cycle) + ", " +
               std::to_string(p.walls.size()) + " walls>";
      });

  py::class_<ContactStats>(m, "ContactStats", "Contact statistics at one cycle")
      .def_readonly("server", &ContactStats::server)
      .def_readonly("cycle", &ContactStats::cycle)
      .def_readonly("time", &ContactStats::time)
      .def_property_readonly("stamp", [](const ContactStats& s) { return seconds_of(s.stamp); })
      .def_readonly("particles", &ContactStats::particles)
      .def_readonly("contacts", &ContactStats::contacts)
      .def_readonly("wall_contacts", &ContactStats::wall_contacts)
      .def_readonly("sliding_contacts", &ContactStats::sliding_contacts)
      .def_readonly("sliding_fraction", &ContactStats::sliding_fraction)
      .def_readonly("coordination_number", &ContactStats::coordination_number)
      .def_readonly("mean_normal_force", &ContactStats::mean_normal_force)
      .def_readonly("max_normal_force", &ContactStats::max_normal_force)
      .def_readonly("histogram_bin_width", &ContactStats::histogram_bin_width)
      .def_readonly("histogram", &ContactStats::histogram,
                    "counts of f = F/mean(F) in bins of histogram_bin_width from 0; the last open-ended")
      .def_readonly("kinetic_energy", &ContactStats::kinetic_energy, "J")
      .def_readonly("out_of_balance", &ContactStats::out_of_balance)
      .def("__repr__", [](const ContactStats& s) {
        return "<ContactStats of " + s.server + " at cycle " + std::to_string(s.cycle) + ": " +
               std::to_string(s.contacts) + " contacts>";
      });

  py::class_<RegionMeasure>(m, "RegionMeasure",
                            "The state of one measurement region (Randall 1989, 4.6; docs/CASES.md, regions.csv)")
      .def_readonly("name", &RegionMeasure::name)
      .def_readonly("particles", &RegionMeasure::particles)
      .def_readonly("rattlers", &RegionMeasure::rattlers)
      .def_readonly("contacts", &RegionMeasure::contacts)
      .def_readonly("particle_contacts", &RegionMeasure::particle_contacts)
      .def_readonly("sliding_contacts", &RegionMeasure::sliding_contacts)
      .def_readonly("sliding_fraction", &RegionMeasure::sliding_fraction)
      .def_readonly("coordination", &RegionMeasure::coordination)
      .def_readonly("mechanical_coordination", &RegionMeasure::mechanical_coordination)
      .def_readonly("porosity", &RegionMeasure::porosity)
      .def_readonly("void_ratio", &RegionMeasure::void_ratio)
      .def_readonly("stress", &RegionMeasure::stress, "Pa, compression positive, row by row")
      .def_readonly("principal_stress", &RegionMeasure::principal_stress, "major first")
      .def_readonly("stress_angle", &RegionMeasure::stress_angle, "2D: the major direction from x, rad")
      .def_readonly("mean_stress", &RegionMeasure::mean_stress)
      .def_readonly("deviator_stress", &RegionMeasure::deviator_stress)
      .def_readonly("sin_phi", &RegionMeasure::sin_phi)
      .def_readonly("tangential_share", &RegionMeasure::tangential_share)
      .def_readonly("fabric", &RegionMeasure::fabric, "<n_i n_j>, row by row (Randall 4.48)")
      .def_readonly("principal_fabric", &RegionMeasure::principal_fabric)
      .def_readonly("fabric_angle", &RegionMeasure::fabric_angle)
      .def_readonly("anisotropy", &RegionMeasure::anisotropy)
      .def_readonly("weighted_fabric", &RegionMeasure::weighted_fabric)
      .def_readonly("principal_weighted_fabric", &RegionMeasure::principal_weighted_fabric)
      .def_readonly("weighted_fabric_angle", &RegionMeasure::weighted_fabric_angle)
      .def_readonly("weighted_anisotropy", &RegionMeasure::weighted_anisotropy)
      .def_readonly("fabric_trace", &RegionMeasure::fabric_trace)
      .def_readonly("mean_normal_force", &RegionMeasure::mean_normal_force)
      .def_readonly("max_normal_force", &RegionMeasure::max_normal_force)
      .def_readonly("mean_rotation", &RegionMeasure::mean_rotation)
      .def_readonly("mean_abs_rotation", &RegionMeasure::mean_abs_rotation)
      .def("__repr__", [](const RegionMeasure& r) {
        return "<RegionMeasure " + r.name + ": " + std::to_string(r.particles) + " particles, mean stress " +
               std::to_string(r.mean_stress) + " Pa>";
      });

  py::class_<RegionTelemetry>(m, "RegionTelemetry", "The measures of a case's regions at one cycle")
      .def_readonly("server", &RegionTelemetry::server)
      .def_readonly("cycle", &RegionTelemetry::cycle)
      .def_readonly("time", &RegionTelemetry::time)
      .def_property_readonly("stamp", [](const RegionTelemetry& t) { return seconds_of(t.stamp); })
      .def_readonly("dimension", &RegionTelemetry::dimension)
      .def_readonly("regions", &RegionTelemetry::regions)
      .def("region",
           [](const RegionTelemetry& t, const std::string& name) -> const RegionMeasure& {
             for (const RegionMeasure& r : t.regions) {
               if (r.name == name) return r;
             }
             throw py::key_error("no region " + name);
           },
           py::arg("name"), py::return_value_policy::reference_internal, "The region of that name")
      .def("__repr__", [](const RegionTelemetry& t) {
        return "<RegionTelemetry of " + t.server + " at cycle " + std::to_string(t.cycle) + ": " +
               std::to_string(t.regions.size()) + " regions>";
      });

  py::class_<Reply>(m, "Reply", "The server's complete reply to one command (chunks joined)")
      .def_readonly("server", &Reply::server)
      .def_readonly("client_id", &Reply::client_id)
      .def_readonly("request_id", &Reply::request_id)
      .def_property_readonly("kind", [](const Reply& r) { return kind_name(r.kind); }, "the command's kind")
      .def_property_readonly("status", [](const Reply& r) { return std::string(to_string(r.status)); })
      .def_readonly("message", &Reply::message)
      .def_readonly("duration", &Reply::duration, "s, from the command's arrival")
      .def_readonly("state", &Reply::state, "the server's status as the reply left")
      .def_readonly("cycles_run", &Reply::cycles_run)
      .def_readonly("condition_met", &Reply::condition_met)
      .def_readonly("plates", &Reply::plates)
      .def_readonly("stats", &Reply::stats)
      .def_readonly("state_hash", &Reply::state_hash)
      .def_readonly("total_contacts", &Reply::total_contacts)
      .def_property_readonly(
          "contacts", [](const Reply& r) { return contact_array(r.contacts); },
          "the contacts as a numpy structured array (dem.CONTACT_DTYPE); a new array on every access")
      .def_readonly("total_bytes", &Reply::total_bytes)
      .def_property_readonly("data", [](const Reply& r) { return py::bytes(r.data); }, "snapshot bytes")
      .def_readonly("path", &Reply::path)
      .def("__repr__", [](const Reply& r) {
        return "<Reply to " + kind_name(r.kind) + ": " + std::string(to_string(r.status)) + ": " + r.message + ">";
      });
}

}  // namespace dem::python
