// The service's messages (dem/protocol/messages.h, generated from the IDL)
// as read-only Python objects: every member by its IDL name, with the IDL's
// comment as its doc (bind_members). Vectors become (x, y, z) tuples, stamps
// seconds since the Unix epoch, enumerations their names ("running",
// "not_found"), and a few members have a form of their own below: command
// kinds their names ("cycle"), bytes bytes, and contacts a numpy structured
// array (contact_array.h).
#include "dem/protocol/messages.h"

#include <pybind11/stl.h>

#include <set>
#include <sstream>
#include <tuple>
#include <type_traits>

#include "bindings.h"
#include "contact_array.h"

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

// Every member of the message as a read-only property, but those in `own`,
// which the caller binds in a form of their own. The names and docs are the
// generated header's string literals, which live as long as the program.
template <class Message>
void bind_members(py::class_<Message>& cls, const std::set<std::string_view>& own = {}) {
  std::apply(
      [&](const auto&... field) {
        (
            [&] {
              if (own.contains(field.name)) return;
              using Member = std::remove_cvref_t<decltype(std::declval<Message>().*field.member)>;
              const auto member = field.member;
              const char* name = field.name.data();
              const char* doc = field.comment.data();
              if constexpr (std::is_same_v<Member, Vector3>) {
                cls.def_property_readonly(
                    name, [member](const Message& m) { return tuple_of(m.*member); }, doc);
              } else if constexpr (std::is_same_v<Member, Stamp>) {
                cls.def_property_readonly(
                    name, [member](const Message& m) { return seconds_of(m.*member); }, "s since the Unix epoch");
              } else if constexpr (std::is_enum_v<Member>) {
                cls.def_property_readonly(
                    name, [member](const Message& m) { return std::string(to_string(m.*member)); }, doc);
              } else {
                cls.def_readonly(name, member, doc);
              }
            }(),
            ...);
      },
      Fields<Message>::list);
}

}  // namespace

void bind_messages(py::module_& m) {
  m.attr("CONTACT_DTYPE") = contact_dtype();

  py::class_<Status> status(m, "Status", "The server's status (durable topic rt/dem/<server>/status)");
  bind_members(status);
  status.def("__repr__", [](const Status& s) {
    std::ostringstream out;
    out << "<Status " << s.server << ": " << to_string(s.state) << ", case " << s.case_name << ", cycle " << s.cycle
        << ">";
    return out.str();
  });

  py::class_<WallForce> wall(m, "WallForce", "One wall's resultants, stress and settlement");
  bind_members(wall);
  wall.def("__repr__", [](const WallForce& w) {
    std::ostringstream out;
    out << "<WallForce " << w.name << ": stress " << w.normal_stress << " Pa, settlement " << w.settlement << " m, "
        << w.contacts << " contacts>";
    return out.str();
  });

  py::class_<PlateForces> plates(m, "PlateForces", "Every wall's forces at one cycle (telemetry or a reply)");
  bind_members(plates);
  plates
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

  py::class_<ContactStats> stats(m, "ContactStats", "Contact statistics at one cycle");
  bind_members(stats);
  stats.def("__repr__", [](const ContactStats& s) {
    return "<ContactStats of " + s.server + " at cycle " + std::to_string(s.cycle) + ": " + std::to_string(s.contacts) +
           " contacts>";
  });

  py::class_<RegionMeasures> region(m, "RegionMeasures",
                                    "The state of one measurement region (Randall 1989, 4.6; docs/CASES.md, "
                                    "regions.csv): stresses in Pa, compression positive; tensors row by row");
  bind_members(region);
  region.def("__repr__", [](const RegionMeasures& r) {
    return "<RegionMeasures " + r.name + ": " + std::to_string(r.particles) + " particles, mean stress " +
           std::to_string(r.mean_stress) + " Pa>";
  });

  py::class_<RegionTelemetry> regions(m, "RegionTelemetry", "The measures of a case's regions at one cycle");
  bind_members(regions);
  regions
      .def(
          "region",
          [](const RegionTelemetry& t, const std::string& name) -> const RegionMeasures& {
            for (const RegionMeasures& r : t.regions) {
              if (r.name == name) return r;
            }
            std::string known;
            for (const RegionMeasures& r : t.regions) known += (known.empty() ? "" : ", ") + r.name;
            throw py::key_error("no region \"" + name + "\" (regions: " + known + ")");
          },
          py::arg("name"), py::return_value_policy::reference_internal,
          "The region of that name; KeyError naming the regions there are otherwise")
      .def("__repr__", [](const RegionTelemetry& t) {
        return "<RegionTelemetry of " + t.server + " at cycle " + std::to_string(t.cycle) + ": " +
               std::to_string(t.regions.size()) + " regions>";
      });

  py::class_<Reply> reply(m, "Reply", "The server's complete reply to one command (chunks joined)");
  bind_members(reply, {"kind", "contacts", "data"});
  reply
      .def_property_readonly(
          "kind", [](const Reply& r) { return kind_name(r.kind); }, "the command's kind")
      .def_property_readonly(
          "contacts", [](const Reply& r) { return contact_array(r.contacts); },
          "the contacts as a numpy structured array (dem.CONTACT_DTYPE); a new array on every access")
      .def_property_readonly(
          "data", [](const Reply& r) { return py::bytes(r.data); }, "snapshot bytes")
      .def("__repr__", [](const Reply& r) {
        return "<Reply to " + kind_name(r.kind) + ": " + std::string(to_string(r.status)) + ": " + r.message + ">";
      });
}

}  // namespace dem::python
