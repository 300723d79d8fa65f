#include "dem/io/snapshot_conversion.h"

#include "snapshot_contacts.h"
#include "snapshot_conversion_fields.h"
#include "snapshot_rules.h"
#include "snapshot_structure_checks.h"

namespace dem::io {

// Where the snapshot's structs live in dem.proto.Snapshot: the state's
// fields in Snapshot itself, its per-particle columns (rotation, force,
// moment) in Snapshot.particles beside the definition's; the definition's
// world settings in Snapshot.settings, its particles, walls and box control
// in Snapshot (a wall's message holds its definition and its state). Every
// other field follows the field lists (snapshot_conversion_fields.h); the
// contact table follows its own (snapshot_contacts.cpp).
template <int Dim>
proto::Snapshot snapshot_to_proto(const WorldSnapshotT<Dim>& s, const SnapshotInfo& info) {
  proto::Snapshot m;
  // Not the engine's state: what the bytes are, and the caller's labels.
  m.set_format(kSnapshotFormat);
  m.set_version(kSnapshotVersion);
  m.set_dimension(Dim);
  m.set_case_name(info.case_name);
  m.set_description(info.description);
  fields::put_struct(s.def, fields::Scope<google::protobuf::Message>(m.mutable_settings(), &m));
  fields::put_struct(s, fields::Scope<google::protobuf::Message>(&m, m.mutable_particles()), {"def"});
  put_contacts<Dim>(s.contacts, *m.mutable_contacts());
  return m;
}

template <int Dim>
WorldSnapshotT<Dim> snapshot_from_proto(const proto::Snapshot& m, SnapshotInfo* info, const ResourceLimits& limits) {
  Problems problems;
  check_structure<Dim>(m, problems, limits);
  if (problems.empty()) check_case_rules<Dim>(m, problems);
  if (!problems.empty()) throw SnapshotError(problems.text());

  WorldSnapshotT<Dim> s;
  fields::get_struct(s.def, fields::Scope<const google::protobuf::Message>(&m.settings(), &m));
  fields::get_struct(s, fields::Scope<const google::protobuf::Message>(&m, &m.particles()), {"def"});
  s.contacts = get_contacts<Dim>(m.contacts());
  if (info != nullptr) *info = SnapshotInfo{m.case_name(), m.description()};
  return s;
}

template <int Dim>
std::vector<std::string> snapshot_schema_problems(int* fields_checked) {
  std::vector<std::string> problems;
  int checked = 0;
  fields::schema_problems<WorldDefT<Dim>>({proto::SnapshotSettings::descriptor(), proto::Snapshot::descriptor()}, "",
                                          {}, problems, checked);
  fields::schema_problems<WorldSnapshotT<Dim>>({proto::Snapshot::descriptor(), proto::SnapshotParticles::descriptor()},
                                               "", {"def"}, problems, checked);
  if (fields_checked != nullptr) *fields_checked = checked;
  return problems;
}

template proto::Snapshot snapshot_to_proto<2>(const WorldSnapshotT<2>&, const SnapshotInfo&);
template proto::Snapshot snapshot_to_proto<3>(const WorldSnapshotT<3>&, const SnapshotInfo&);
template WorldSnapshotT<2> snapshot_from_proto<2>(const proto::Snapshot&, SnapshotInfo*, const ResourceLimits&);
template WorldSnapshotT<3> snapshot_from_proto<3>(const proto::Snapshot&, SnapshotInfo*, const ResourceLimits&);
template std::vector<std::string> snapshot_schema_problems<2>(int*);
template std::vector<std::string> snapshot_schema_problems<3>(int*);

}  // namespace dem::io
