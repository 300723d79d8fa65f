#include <algorithm>
#include <string>

#include "dem/error.h"
#include "world_state.h"

namespace dem {

namespace {

template <int Dim>
ContactSnapshotT<Dim> save_contact(const ContactState<Dim>& s, const ContactForce<Dim>& f) {
  ContactSnapshotT<Dim> c;
  c.normal_force = s.normal_force;
  c.shear_force = s.shear;
  c.sliding = s.sliding;
  c.overlap = s.overlap;
  c.normal_damping = s.normal_damping;
  c.shear_damping = s.shear_damping;
  c.normal = s.normal;
  c.point = s.point;
  c.force = f.force;
  c.moment_first = f.moment_first;
  c.moment_second = f.moment_second;
  c.formed_cycle = s.formed_cycle;
  c.touching = s.touching;
  c.mindlin = s.mindlin;
  c.mindlin_axis = s.mindlin_axis;
  c.dashpot_force = s.dashpot_force;
  c.relative_velocity = s.relative_velocity;
  c.search_first = s.search_first;
  c.search_second = s.search_second;
  c.has_search = s.has_search;
  return c;
}

template <int Dim>
void restore_contact(const ContactSnapshotT<Dim>& c, ContactState<Dim>& s, ContactForce<Dim>& f) {
  s.normal_force = c.normal_force;
  s.shear = c.shear_force;
  s.touching = c.touching;
  s.sliding = c.sliding;
  s.overlap = c.overlap;
  s.normal_damping = c.normal_damping;
  s.shear_damping = c.shear_damping;
  s.normal = c.normal;
  s.point = c.point;
  s.formed_cycle = c.formed_cycle;
  s.mindlin = c.mindlin;
  s.mindlin_axis = c.mindlin_axis;
  s.dashpot_force = c.dashpot_force;
  s.relative_velocity = c.relative_velocity;
  s.search_first = c.search_first;
  s.search_second = c.search_second;
  s.has_search = c.has_search;
  f = ContactForce<Dim>{c.force, c.moment_first, c.moment_second};
}

void check(bool ok, const std::string& message) {
  if (!ok) throw DefinitionError("snapshot: " + message);
}

// The table row of a saved contact; every touching pair is within the
// tolerance, so the broad phase has put it in the table.
template <typename Contact, typename Key>
std::size_t find_row(const std::vector<Contact>& rows, ParticleId first, std::int32_t second, Key key) {
  const auto it = std::lower_bound(rows.begin(), rows.end(), std::pair{first, second},
                                   [&](const Contact& c, const std::pair<ParticleId, std::int32_t>& k) {
                                     return key(c) < k;
                                   });
  check(it != rows.end() && key(*it) == std::pair{first, second},
        "contact (" + std::to_string(first) + ", " + std::to_string(second) + ") does not touch");
  return static_cast<std::size_t>(it - rows.begin());
}

// The table's rows as saved, so the contact search and the next rebuild
// happen as they would have. A snapshot without the bookkeeping (written by
// hand or by another tool) gets a table rebuilt from the current positions,
// which every touching contact must be in.
template <int Dim>
void restore_contact_table(WorldState<Dim>& s, const WorldSnapshotT<Dim>& snap) {
  const auto n = static_cast<ParticleId>(s.particles.size());
  for (const ContactSnapshotT<Dim>& c : snap.contacts) {
    check(c.first >= 0 && c.first < n, "contact names particle " + std::to_string(c.first));
    if (c.with_wall) {
      check(c.second >= 0 && c.second < s.walls.size(), "contact names wall " + std::to_string(c.second));
    } else {
      check(c.second > c.first && c.second < n, "contact names particle " + std::to_string(c.second));
    }
  }
  const bool saved_rows = !snap.reference_positions.empty();
  ContactTable<Dim>& t = s.contacts;
  if (saved_rows) {
    check(snap.reference_positions.size() == s.particles.size(),
          "reference positions do not match the " + std::to_string(n) + " particles");
    std::vector<Candidate> pairs, walls;
    for (const ContactSnapshotT<Dim>& c : snap.contacts) (c.with_wall ? walls : pairs).push_back({c.first, c.second});
    auto key = [](const Candidate& c) { return std::pair{c.first, c.second}; };
    for (auto* keys : {&pairs, &walls}) {
      std::sort(keys->begin(), keys->end(), [&](const Candidate& a, const Candidate& b) { return key(a) < key(b); });
      for (std::size_t k = 1; k < keys->size(); ++k) {
        check(key((*keys)[k]) != key((*keys)[k - 1]), "contact (" + std::to_string((*keys)[k].first) + ", " +
                                                          std::to_string((*keys)[k].second) + ") appears twice");
      }
    }
    rebuild_contacts(t, pairs, walls, static_cast<int>(n));
    s.reference_positions = snap.reference_positions;
    s.particle_travel = snap.particle_travel;
    s.wall_travel = snap.wall_travel;
    s.contacts_stale = snap.contacts_stale;
  } else {
    find_contacts(s);
  }
  for (const ContactSnapshotT<Dim>& c : snap.contacts) {
    if (!saved_rows && !c.touching) continue;  // only history matters in a rebuilt table
    if (c.with_wall) {
      const std::size_t k =
          find_row(t.walls, c.first, c.second, [](const WallContact<Dim>& w) { return std::pair{w.particle, w.wall}; });
      restore_contact(c, t.walls[k].state, t.wall_forces[k]);
    } else {
      const std::size_t k =
          find_row(t.pairs, c.first, c.second, [](const PairContact<Dim>& p) { return std::pair{p.first, p.second}; });
      restore_contact(c, t.pairs[k].state, t.pair_forces[k]);
    }
  }
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
  def.planar_particle = s.planar_particle;
  def.periodic = s.periodic_def;
  def.contact_tolerance = s.contact_tolerance;
  def.threads = s.threads;
  def.fixed_time_step = s.fixed_time_step;
  def.time_step_fraction = s.time_step_fraction;
  const Particles<Dim>& p = s.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    def.particles.push_back(ParticleDefT<Dim>{p.position[i], p.radius[i], p.material[i], p.velocity[i],
                                              p.angular_velocity[i], p.shape[i]});
  }
  snap.rotation = p.rotation;
  snap.force = p.force;
  snap.moment = p.moment;
  const Walls<Dim>& walls = s.walls;
  def.walls = walls.def;
  for (int w = 0; w < walls.size(); ++w) {
    snap.walls.push_back(WallSnapshotT<Dim>{walls.initial_point[w], walls.last_velocity[w],
                                            walls.last_angular_velocity[w], walls.force[w], walls.moment[w],
                                            walls.normal_force[w], walls.contacts[w], walls.normal_force_arm[w]});
  }
  const ContactTable<Dim>& t = s.contacts;
  for (std::size_t k = 0; k < t.pairs.size(); ++k) {
    ContactSnapshotT<Dim> c = save_contact(t.pairs[k].state, t.pair_forces[k]);
    c.first = t.pairs[k].first;
    c.second = t.pairs[k].second;
    snap.contacts.push_back(c);
  }
  for (std::size_t k = 0; k < t.walls.size(); ++k) {
    ContactSnapshotT<Dim> c = save_contact(t.walls[k].state, t.wall_forces[k]);
    c.first = t.walls[k].particle;
    c.second = t.walls[k].wall;
    c.with_wall = true;
    snap.contacts.push_back(c);
  }
  snap.reference_positions = s.reference_positions;
  snap.particle_travel = s.particle_travel;
  snap.wall_travel = s.wall_travel;
  snap.contacts_stale = s.contacts_stale;
  snap.energy = s.energy;
  snap.tangential_work = s.tangential_work;
  snap.cycle = s.cycle;
  snap.time = s.time;
  snap.time_step = s.time_step;
  snap.critical_time_step = s.critical_time_step;
  return snap;
}

template <int Dim>
void restore_snapshot(WorldState<Dim>& s, const WorldSnapshotT<Dim>& snap) {
  const std::size_t n = s.particles.size();
  check(snap.rotation.size() == n && snap.force.size() == n && snap.moment.size() == n,
        "per-particle arrays do not match the " + std::to_string(n) + " particles");
  check(snap.walls.size() == s.walls.def.size(), "per-wall records do not match the walls");
  check(snap.time_step > 0.0 && snap.critical_time_step > 0.0, "time step must be > 0");
  s.particles.rotation = snap.rotation;
  s.particles.force = snap.force;
  s.particles.moment = snap.moment;
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

  restore_contact_table(s, snap);
}

template WorldSnapshotT<2> save_snapshot(const WorldState<2>&);
template WorldSnapshotT<3> save_snapshot(const WorldState<3>&);
template void restore_snapshot(WorldState<2>&, const WorldSnapshotT<2>&);
template void restore_snapshot(WorldState<3>&, const WorldSnapshotT<3>&);

}  // namespace dem
