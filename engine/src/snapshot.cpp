#include <algorithm>
#include <string>

#include "contact_fields.h"
#include "contact_forces.h"
#include "contact_history.h"
#include "dem/error.h"
#include "particle_fields.h"
#include "particle_order.h"
#include "world_state.h"

namespace dem {

namespace {

// A row's history, as the snapshot holds it: the key, the flags and every
// column the table keeps (contact_fields.h).
template <int Dim>
ContactSnapshotT<Dim> save_row(const ContactRows<Dim>& rows, std::size_t r, const Particles<Dim>& p, bool wall) {
  ContactSnapshotT<Dim> c;
  c.first = p.id[rows.first[r]].value();
  c.second = wall ? rows.second[r] : p.id[rows.second[r]].value();
  c.with_wall = wall;
  c.touching = rows.touching(r);
  c.sliding = rows.sliding(r);
  for_each_kept_field<Dim>(rows, r, [&](const ContactFieldInfo&, auto field, const auto& value) { field(c) = value; });
  return c;
}

template <int Dim>
void restore_row(const ContactSnapshotT<Dim>& c, ContactRows<Dim>& rows, std::size_t r) {
  rows.flags[r] = static_cast<std::uint8_t>((c.touching ? kTouching : 0) | (c.sliding ? kSliding : 0));
  for_each_kept_field<Dim>(rows, r, [&](const ContactFieldInfo&, auto field, auto& value) { value = field(c); });
}

void check(bool ok, const std::string& message) {
  if (!ok) throw DefinitionError("snapshot: " + message);
}

// A column's value as its definition field holds it: material indices as ids.
template <typename T>
void save_value(T& saved, const T& value) {
  saved = value;
}
template <typename Tag>
void save_value(Id<Tag>& saved, std::int32_t value) {
  saved = Id<Tag>{value};
}

// Whether every saved per-particle vector of `role` has an entry per particle.
template <int Dim>
bool columns_match(const WorldSnapshotT<Dim>& snap, std::size_t n, ParticleFieldRole role) {
  bool match = true;
  for_each_particle_field<Dim>([&](const ParticleFieldInfo& info, auto, auto saved, auto) {
    if constexpr (kInSnapshot<decltype(saved)>) {
      if (info.role == role && saved.field(snap).size() != n) match = false;
    }
  });
  return match;
}

// The saved per-particle vectors of `role` into their columns: the k-th
// entry is the particle of the k-th id.
template <int Dim>
void restore_columns(Particles<Dim>& p, const WorldSnapshotT<Dim>& snap, ParticleFieldRole role) {
  for_each_particle_field<Dim>([&](const ParticleFieldInfo& info, auto column, auto saved, auto) {
    if constexpr (kInSnapshot<decltype(saved)>) {
      if (info.role != role) return;
      auto& values = column(p);
      const auto& from = saved.field(snap);
      for (std::size_t k = 0; k < p.ids.size(); ++k) values[static_cast<std::size_t>(p.slot_of(p.ids[k]))] = from[k];
    }
  });
}

// Each particle by id into the definition's particles and the snapshot's
// per-particle vectors, as the field list says (particle_fields.h).
template <int Dim>
void save_particles(const Particles<Dim>& p, WorldSnapshotT<Dim>& snap) {
  const std::size_t n = p.size();
  snap.def.particles.reserve(n);
  for_each_particle_field<Dim>([&](const ParticleFieldInfo&, auto, auto saved, auto) {
    if constexpr (kInSnapshot<decltype(saved)>) saved.field(snap).reserve(n);
  });
  for (const ParticleId id : p.ids) {
    const auto i = static_cast<std::size_t>(p.slot_of(id));
    ParticleDefT<Dim>& d = snap.def.particles.emplace_back();
    for_each_particle_field<Dim>([&](const ParticleFieldInfo&, auto column, auto saved, auto) {
      const auto& values = column(p);
      if constexpr (kInDefinition<decltype(saved)>) {
        if (!values.empty()) save_value(saved.field(d), values[i]);  // an empty optional column: the default
      } else if constexpr (kInSnapshot<decltype(saved)>) {
        saved.field(snap).push_back(values[i]);
      }
    });
  }
}

// The row of a key in a sorted table.
template <int Dim>
std::size_t find_row(const ContactRows<Dim>& rows, const ContactKey& key, const std::string& what) {
  const auto it = std::lower_bound(rows.first.begin(), rows.first.end(), key.first);
  for (auto r = static_cast<std::size_t>(it - rows.first.begin()); r < rows.size() && rows.first[r] == key.first; ++r) {
    if (rows.second[r] == key.second) return r;
  }
  check(false, "contact " + what + " does not touch");
  return 0;
}

// The table's rows as saved, so the contact search and the next rebuild
// happen as they would have. A snapshot without the bookkeeping (written by
// hand or by another tool) gets a table rebuilt from the current positions,
// which every touching contact must be in.
template <int Dim>
void restore_contact_table(WorldState<Dim>& s, const WorldSnapshotT<Dim>& snap) {
  const Particles<Dim>& p = s.particles;
  const auto n = static_cast<std::int32_t>(p.size());
  const auto known = [&](std::int32_t id) { return p.contains(ParticleId{id}); };
  // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on "(" + std::string once inlined here.
  auto name = [](const ContactSnapshotT<Dim>& c) {
    std::string text = "(";
    text += std::to_string(c.first);
    text += ", ";
    text += std::to_string(c.second);
    text += ")";
    return text;
  };
  auto key = [&](const ContactSnapshotT<Dim>& c) {
    return ContactKey{p.slot[c.first], c.with_wall ? c.second : p.slot[c.second]};
  };
  for (const ContactSnapshotT<Dim>& c : snap.contacts) {
    check(known(c.first), "contact names particle " + std::to_string(c.first));
    if (c.with_wall) {
      check(c.second >= 0 && c.second < s.walls.size(), "contact names wall " + std::to_string(c.second));
    } else {
      check(c.second > c.first && known(c.second), "contact names particle " + std::to_string(c.second));
    }
  }
  const bool saved_rows = !snap.reference_positions.empty();
  ContactTable<Dim>& t = s.contacts;
  if (saved_rows) {
    check(columns_match(snap, p.size(), ParticleFieldRole::kBookkeeping),
          "reference positions do not match the " + std::to_string(n) + " particles");
    std::vector<ContactKey> pairs, walls;
    for (const ContactSnapshotT<Dim>& c : snap.contacts) (c.with_wall ? walls : pairs).push_back(key(c));
    for (auto* keys : {&pairs, &walls}) {
      std::sort(keys->begin(), keys->end());
      const auto twice = std::adjacent_find(keys->begin(), keys->end());
      check(twice == keys->end(), "a contact appears twice");
    }
    merge_rows(t.pairs, pairs);
    merge_rows(t.walls, walls);
    restore_columns(s.particles, snap, ParticleFieldRole::kBookkeeping);
    s.particle_travel = snap.particle_travel;
    s.wall_travel = snap.wall_travel;
    s.contacts_stale = snap.contacts_stale;
    plan_blocks(s.blocks, t, p.size(), block_size(s));
  } else {
    find_contacts(s, current_context(s));
  }
  for (const ContactSnapshotT<Dim>& c : snap.contacts) {
    if (!saved_rows && !c.touching) continue;  // only history matters in a rebuilt table
    ContactRows<Dim>& rows = c.with_wall ? t.walls : t.pairs;
    restore_row(c, rows, find_row(rows, key(c), name(c)));
  }
}

// Gives the particles, just built in definition order (slot k holds
// def.particles[k]), their saved ids.
template <int Dim>
void restore_ids(WorldState<Dim>& s, const WorldSnapshotT<Dim>& snap) {
  if (snap.particle_ids.empty()) return;
  Particles<Dim>& p = s.particles;
  const std::size_t n = p.size();
  check(snap.particle_ids.size() == n, "particle ids do not match the " + std::to_string(n) + " particles");
  for (std::size_t k = 0; k < n; ++k) {
    const ParticleId id = snap.particle_ids[k];
    check(id.valid() && (k == 0 || snap.particle_ids[k - 1] < id), "particle ids must ascend from 0");
  }
  const auto given = static_cast<std::size_t>(snap.particle_ids.back().value()) + 1;
  check(snap.particle_id_count == 0 || static_cast<std::size_t>(snap.particle_id_count) >= given,
        "particle_id_count " + std::to_string(snap.particle_id_count) + " is below the ids");
  p.id = snap.particle_ids;
  p.index_ids(std::max(given, static_cast<std::size_t>(snap.particle_id_count)));
}

// Puts the particles in the saved storage order.
template <int Dim>
void restore_order(WorldState<Dim>& s, const WorldSnapshotT<Dim>& snap) {
  if (snap.particle_order.empty()) return;
  const std::size_t n = s.particles.size();
  check(snap.particle_order.size() == n, "particle order does not match the " + std::to_string(n) + " particles");
  const Particles<Dim>& p = s.particles;
  std::vector<bool> seen(p.slot.size(), false);
  std::vector<Slot> order;
  order.reserve(n);
  for (ParticleId id : snap.particle_order) {
    check(p.contains(id) && !seen[id.index()], "particle order is not a permutation of the ids");
    seen[id.index()] = true;
    order.push_back(p.slot_of(id));
  }
  // The state was just built in id order: slot k takes particle order[k].
  reorder_particles(s.particles, s.contacts, order);
  s.sorted_cycle = snap.sorted_cycle;
}

}  // namespace

template <int Dim>
WorldSnapshotT<Dim> save_snapshot(const WorldState<Dim>& s) {
  WorldSnapshotT<Dim> snap;
  WorldDefT<Dim>& def = snap.def;
  def.materials = s.materials;
  def.contact_models = s.contact_models;
  def.damping = s.damping;
  def.gravity = s.gravity;
  def.centripetal_gravity = s.centripetal_gravity;
  def.planar_particle = s.planar_particle;
  def.periodic = s.periodic_def;
  def.contact_tolerance = s.contact_tolerance;
  def.threads = s.threads;
  def.fixed_time_step = s.fixed_time_step;
  def.time_step_fraction = s.time_step_fraction;
  def.energy_budget = s.energy_budget;
  const Particles<Dim>& p = s.particles;
  const std::size_t n = p.size();
  save_particles(p, snap);
  // Ids are saved once something was removed (they are 0 .. n-1 before).
  if (p.slot.size() != n) {
    snap.particle_ids = p.ids;
    snap.particle_id_count = static_cast<std::int32_t>(p.slot.size());
  }
  snap.particle_order = p.id;
  snap.sorted_cycle = s.sorted_cycle == kNeverSorted ? 0 : s.sorted_cycle;
  if (s.sorted_cycle == kNeverSorted) snap.particle_order.clear();
  const Walls<Dim>& walls = s.walls;
  def.walls = walls.def;
  def.box_control = walls.box;
  for (int w = 0; w < walls.size(); ++w) {
    snap.walls.push_back(WallSnapshotT<Dim>{walls.initial_point[w], walls.last_velocity[w],
                                            walls.last_angular_velocity[w], walls.force[w], walls.moment[w],
                                            walls.normal_force[w], walls.contacts[w], walls.normal_force_arm[w]});
  }
  const ContactTable<Dim>& t = s.contacts;
  snap.contacts.reserve(t.pairs.size() + t.walls.size());
  for (std::size_t r = 0; r < t.pairs.size(); ++r) snap.contacts.push_back(save_row(t.pairs, r, p, false));
  for (std::size_t r = 0; r < t.walls.size(); ++r) snap.contacts.push_back(save_row(t.walls, r, p, true));
  // What the last pass made of the touching rows, for readers.
  visit_touching_rows<Dim>(s, [&](const RowReport<Dim>& report) {
    ContactSnapshotT<Dim>& c = snap.contacts[report.wall ? t.pairs.size() + report.row : report.row];
    const ContactRecordT<Dim>& record = report.record;
    c.normal_force = record.normal_force;
    c.overlap = record.overlap;
    c.normal_damping = record.normal_damping;
    c.shear_damping = report.shear_damping;
    c.normal = record.normal;
    c.point = record.point;
    c.force = report.force;
    c.moment_first = report.moment_first;
    c.moment_second = report.moment_second;
  });
  snap.particle_travel = s.particle_travel;
  snap.wall_travel = s.wall_travel;
  snap.contacts_stale = s.contacts_stale;
  snap.energy = s.energy;
  snap.tangential_work = s.tangential_work;
  snap.cycle = s.cycle;
  snap.time = s.time;
  snap.time_step = s.time_step;
  snap.critical_time_step = s.critical_time_step;
  snap.continuum = s.continuum;
  return snap;
}

template <int Dim>
void restore_snapshot(WorldState<Dim>& s, const WorldSnapshotT<Dim>& snap) {
  const std::size_t n = s.particles.size();
  check(columns_match(snap, n, ParticleFieldRole::kState),
        "per-particle arrays do not match the " + std::to_string(n) + " particles");
  check(snap.walls.size() == s.walls.def.size(), "per-wall records do not match the walls");
  check(snap.time_step > 0.0 && snap.critical_time_step > 0.0, "time step must be > 0");
  restore_ids(s, snap);
  restore_order(s, snap);
  // The per-particle arrays follow def.particles: the k-th entry is the
  // particle of the k-th id.
  restore_columns(s.particles, snap, ParticleFieldRole::kState);
  for (std::size_t w = 0; w < snap.walls.size(); ++w) {
    const WallSnapshotT<Dim>& ws = snap.walls[w];
    s.walls.initial_point[w] = ws.initial_point;
    s.walls.last_velocity[w] = ws.last_velocity;
    s.walls.last_angular_velocity[w] = ws.last_angular_velocity;
    s.walls.force[w] = ws.force;
    s.walls.moment[w] = ws.moment;
    s.walls.normal_force[w] = ws.normal_force;
    s.walls.contacts[w] = ws.contacts;
    s.walls.normal_force_arm[w] = ws.normal_force_arm;
  }
  s.energy = snap.energy;
  s.tangential_work = snap.tangential_work;
  s.cycle = snap.cycle;
  s.time = snap.time;
  s.time_step = snap.time_step;
  s.critical_time_step = snap.critical_time_step;
  s.continuum = snap.continuum;
  restore_contact_table(s, snap);
}

template WorldSnapshotT<2> save_snapshot(const WorldState<2>&);
template WorldSnapshotT<3> save_snapshot(const WorldState<3>&);
template void restore_snapshot(WorldState<2>&, const WorldSnapshotT<2>&);
template void restore_snapshot(WorldState<3>&, const WorldSnapshotT<3>&);

}  // namespace dem
