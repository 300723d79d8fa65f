#include "contact_forces.h"

#include <omp.h>

#include <algorithm>
#include <type_traits>

#include "contact_batch.h"
#include "contact_row.h"
#include "ellipsoid_rows.h"
#include "fetch_ahead.h"
#include "law_dispatch.h"
#include "wall_batch.h"
#include "world_state.h"

namespace dem {

namespace {

// Where the pair rows of block b put the second particle's share: into its
// sums when the block holds it, else into the slot set aside for it
// (contact_blocks.h), which the pass adds once every block is done.
template <int Dim>
class PairShares {
 public:
  using Body = ParticleBody<Dim>;
  PairShares(const PassInputs<Dim>&, ContactBlocks<Dim>& blocks, int b, WallSum<Dim>*)
      : begin(blocks.pair_begin[b]),
        end(blocks.pair_begin[b + 1]),
        blocks_(blocks),
        cross_(blocks.cross_begin[b]),
        cross_end_(blocks.cross_begin[b + 1]),
        next_cross_(cross_ < cross_end_ ? blocks.cross_row[cross_] : -1) {}

  const std::int32_t begin, end;  // the block's pair rows

  // Row r is next: is it one that crosses to another block?
  void next(std::int32_t r) {
    aside_ = -1;
    if (r == next_cross_) {
      aside_ = blocks_.cross_slot[cross_++];
      next_cross_ = cross_ < cross_end_ ? blocks_.cross_row[cross_] : -1;
    }
  }
  // The row does not touch: its set-aside share, if it has one, is nothing.
  void apart() {
    if (aside_ < 0) return;
    blocks_.deferred_force[aside_] = Vec<Dim>::Zero();
    blocks_.deferred_moment[aside_] = Space<Dim>::zero_spin();
  }
  void add(Particles<Dim>& p, Slot y, const RowResult<Dim>& c) {
    if (aside_ >= 0) {
      blocks_.deferred_force[aside_] = -c.force;
      blocks_.deferred_moment[aside_] = c.moment_second;
    } else {
      p.force[y] -= c.force;
      p.moment[y] += c.moment_second;
    }
  }

 private:
  ContactBlocks<Dim>& blocks_;
  std::int32_t cross_, cross_end_, next_cross_;
  std::int32_t aside_ = -1;
};

// Where the wall rows of block b put the wall's share: the block's own sum
// for each wall, added up over the blocks in block order after the pass.
template <int Dim>
class WallShares {
 public:
  using Body = WallBody<Dim>;
  WallShares(const PassInputs<Dim>& in, ContactBlocks<Dim>& blocks, int b, WallSum<Dim>* sums)
      : begin(blocks.wall_begin[b]), end(blocks.wall_begin[b + 1]), walls_(in.walls), sums_(sums) {}

  const std::int32_t begin, end;  // the block's wall rows

  void next(std::int32_t) {}
  void apart() {}
  void add(Particles<Dim>&, std::int32_t w, const RowResult<Dim>& c) {
    const WallDefT<Dim>& wall = walls_.def[w];
    add_wall_share(sums_[w], wall, c.geometry.point, c.force, closest_point(wall, c.geometry.point).coordinates);
  }

 private:
  const Walls<Dim>& walls_;
  WallSum<Dim>* sums_;
};

// The rows of block b, pairs or walls (Shares): each row's forces, the
// first particle's share into its sums, the second body's where Shares
// puts it. Flattened: with the row body written once over its policies,
// GCC stopped inlining the geometry, the history's load and the result's
// constructor into the wall rows (callgrind, 10k plate benchmark: +80
// instructions a wall row); everything a row calls in this file is inlined.
template <Pass kPass, bool kEnergy, typename Law, typename Shape, typename Shares, int Dim>
[[gnu::flatten]] void row_block(const PassInputs<Dim>& in, Particles<Dim>& p, ContactRows<Dim>& rows,
                                ContactBlocks<Dim>& blocks, int b, ContactEnergy& energy, WallSum<Dim>* wall_sums) {
  using Body = typename Shares::Body;
  Shares shares(in, blocks, b, wall_sums);
  const auto add = [&](std::int32_t r, const RowResult<Dim>& c) {
    shares.next(r);
    if (!c.touching) {
      shares.apart();
      return;
    }
    const Slot x = rows.first[r];
    p.force[x] += c.force;
    p.moment[x] += c.moment_first;
    shares.add(p, rows.second[r], c);
  };
  if constexpr (std::is_same_v<Shape, EllipsoidShape> && !Body::kWall) {
    // Ellipsoid pairs: a run of rows' geometry first, the searches several
    // at a time across a vector's lanes (ellipsoid_rows.h), then each row
    // as below; the same bits. A pass that only evaluates leaves the rows'
    // search state as it was.
    constexpr int kRun = 64;
    ContactGeometry<3> geometry[kRun];
    ContactSearch scratch[kRun];
    for (std::int32_t run = shares.begin; run < shares.end; run += kRun) {
      const int count = std::min<std::int32_t>(kRun, shares.end - run);
      ContactSearch* search = scratch;
      if constexpr (kPass == Pass::kAdvance) {
        search = rows.search.data() + run;
      } else {
        std::copy(rows.search.begin() + run, rows.search.begin() + run + count, scratch);
      }
      ellipsoid_pair_geometry<kEnergy>(in, rows.first.data() + run, rows.second.data() + run, search, count, geometry);
      for (int k = 0; k < count; ++k) {
        const std::int32_t r = run + k;
        Body second(in, rows.second[r]);
        add(r, contact_row_from<kPass, kEnergy, Law, Shape, Body>(in, rows, r, second, geometry[k], energy));
      }
    }
  } else {
    for (std::int32_t r = shares.begin; r < shares.end; ++r) {
      add(r, contact_row<kPass, kEnergy, Law, Shape, Body>(in, rows, r, energy));
    }
  }
}

// Calls pass.template operator()<Shape>() with the particles' shape policy.
template <int Dim, typename Run>
void with_shape(ShapeKind shape, Run&& run) {
  if constexpr (Dim == 2) {
    if (shape == ShapeKind::kSuperquadric) {
      run.template operator()<SuperquadricShape>();
      return;
    }
  } else {
    if (shape == ShapeKind::kEllipsoid) {
      run.template operator()<EllipsoidShape>();
      return;
    }
  }
  run.template operator()<RoundShape>();
}

template <typename Run>
void with_energy(bool energy, Run&& run) {
  if (energy) {
    run.template operator()<true>();
  } else {
    run.template operator()<false>();
  }
}

// One block of one table (row_block, or the batched pass): its rows'
// energy flows, and for wall rows each wall's sum of the block.
template <int Dim>
using BlockFn = void (*)(const PassInputs<Dim>&, Particles<Dim>&, ContactRows<Dim>&, ContactBlocks<Dim>&, int,
                         ContactEnergy&, WallSum<Dim>*);

// The parameter sets the rows of each table resolve to (parameter_sets.h),
// found from the materials in use at each pass (a scan of the particles'
// material ids, 4 bytes a particle), so no edit has to keep them up to date.
struct PassSets {
  RowSets pair, wall;
};

template <int Dim>
PassSets pass_sets(const WorldState<Dim>& s) {
  const Column<std::int32_t>& material = s.particles.material;
  std::vector<std::int32_t> particle_materials;
  if (!material.empty()) particle_materials.push_back(material[0]);
  std::int32_t differ = 0;  // a vector loop: any id other than the first leaves a bit set
  for (const std::int32_t m : material) differ |= m ^ material[0];
  if (differ != 0) {
    // A vector loop per material: marking each particle's in a table of
    // flags, one store after another, cost the pass 1 % (10k bed, perf).
    particle_materials.clear();
    for (std::int32_t m = 0; m < static_cast<std::int32_t>(s.materials.size()); ++m) {
      std::int32_t found = 0;
      for (const std::int32_t id : material) found |= static_cast<std::int32_t>(id == m);
      if (found != 0) particle_materials.push_back(m);
    }
  }
  std::vector<std::int32_t> wall_materials;
  for (const WallDefT<Dim>& wall : s.walls.def) wall_materials.push_back(wall.material.value());
  return {row_sets(s.params, particle_materials, particle_materials),
          row_sets(s.params, particle_materials, wall_materials)};
}

// What the rows of a pass read: the state's bodies and parameters, the
// step's dt and cycle; the batched passes the tables' parameter sets.
template <int Dim>
PassInputs<Dim> inputs(const WorldState<Dim>& s, const StepContext& step, const std::vector<EllipsoidFrame>& frames,
                       const PassSets* sets = nullptr) {
  return {
      s.particles, s.walls,    s.periodic,     s.params,     sets ? &sets->pair : nullptr, sets ? &sets->wall : nullptr,
      step.dt,     step.cycle, near_margin(s), frames.data()};
}

// Each ellipsoid's matrices, once per pass rather than once per contact
// (a body has about ten rows): particles begin to end.
template <int Dim>
void frame_ellipsoids(const Particles<Dim>& p, std::vector<EllipsoidFrame>& frames, std::int64_t begin,
                      std::int64_t end) {
  if constexpr (Dim == 3) ellipsoid_frames_of(p, frames.data(), begin, end);
}

template <typename Law, int Dim, SetChoice kSets, bool kPrefetch, bool kHot>
void batched_pair_rows(const PassInputs<Dim>& in, Particles<Dim>& p, ContactRows<Dim>& rows, ContactBlocks<Dim>& blocks,
                       int b, ContactEnergy&, WallSum<Dim>*) {
  batched_pair_block<Law, Dim, kSets, kPrefetch, kHot>(in, p, rows, blocks, b);
}

template <typename Law, int Dim, SetChoice kSets>
void batched_wall_rows(const PassInputs<Dim>& in, Particles<Dim>& p, ContactRows<Dim>& rows, ContactBlocks<Dim>& blocks,
                       int b, ContactEnergy&, WallSum<Dim>* wall_sums) {
  batched_wall_block<Law, Dim, kSets>(in, p, rows, blocks, b, wall_sums);
}

// Calls run.template operator()<kSets>() with how a table's law loop reads
// its rows' parameter sets.
template <typename Run>
void with_sets(const RowSets& sets, Run&& run) {
  switch (sets.choice()) {
    case SetChoice::kOne:
      run.template operator()<SetChoice::kOne>();
      break;
    case SetChoice::kFew:
      run.template operator()<SetChoice::kFew>();
      break;
    case SetChoice::kMany:
      run.template operator()<SetChoice::kMany>();
      break;
  }
}

// Runs the chosen pass over every block, then adds the shares set aside,
// then sums the walls' shares in block order.
template <Pass kPass, int Dim>
ContactEnergy run_pass(WorldState<Dim>& s, const StepContext& step) {
  const bool ellipsoids = s.shape == ShapeKind::kEllipsoid;
  if (ellipsoids) s.ellipsoid_frames.resize(s.particles.size());
  PassSets sets;
  if constexpr (kPass == Pass::kAdvance) sets = pass_sets(s);
  const PassInputs<Dim> in = inputs(s, step, s.ellipsoid_frames, &sets);
  BlockFn<Dim> pair_fn = nullptr;
  bool hot = false;  // the batched pass reads the particles' side-by-side copies (contact_batch.h)
  BlockFn<Dim> wall_fn = nullptr;
  const bool energy = step.energy_budget && kPass == Pass::kAdvance;
  with_energy(energy, [&]<bool kEnergy>() {
    with_shape<Dim>(s.shape, [&]<typename Shape>() {
      with_law(s.pair_law, [&]<typename Law>() {
        pair_fn = &row_block<kPass, kEnergy, Law, Shape, PairShares<Dim>, Dim>;
        if constexpr (kPass == Pass::kAdvance && !kEnergy && kBatchableShape<Shape> && Law::kBatchable) {
          const bool large = static_cast<std::int64_t>(s.particles.size()) > kPrefetchParticles;
          hot = large || Dim == 3;  // (contact_blocks.h, HotPlace)
          with_sets(sets.pair, [&]<SetChoice kSets>() {
            if (large) {
              pair_fn = &batched_pair_rows<Law, Dim, kSets, true, true>;
            } else {
              pair_fn = hot ? &batched_pair_rows<Law, Dim, kSets, false, true>
                            : &batched_pair_rows<Law, Dim, kSets, false, false>;
            }
          });
        }
      });
      with_law(s.wall_law, [&]<typename Law>() {
        wall_fn = &row_block<kPass, kEnergy, Law, Shape, WallShares<Dim>, Dim>;
        if constexpr (kPass == Pass::kAdvance && !kEnergy && kBatchableShape<Shape> && Law::kBatchable) {
          if (planar_walls(s.walls)) {
            with_sets(sets.wall, [&]<SetChoice kSets>() { wall_fn = &batched_wall_rows<Law, Dim, kSets>; });
          }
        }
      });
    });
  });
  ContactBlocks<Dim>& blocks = s.blocks;
  Particles<Dim>& p = s.particles;
  if (hot) {
    blocks.hot_place.resize(p.size());
    blocks.hot_motion.resize(p.size());
  }
  const bool copy_hot = hot && !blocks.hot_fresh;  // else the law of motion wrote them (motion.cpp)
  blocks.hot_fresh = false;
  const int count = blocks.count();
  const int walls = s.walls.size();
  std::vector<WallSum<Dim>> wall_sums(static_cast<std::size_t>(count) * walls);
  std::vector<ContactEnergy> energies(static_cast<std::size_t>(count));
  const int threads = count > 1 ? step.threads : 1;
  const bool shaped = s.shape != ShapeKind::kRound;
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    if (copy_hot) {
#pragma omp for schedule(static)
      for (int b = 0; b < count; ++b)
        copy_hot_particles(p, blocks.hot_place.data(), blocks.hot_motion.data(), blocks.particle_begin[b],
                           blocks.particle_begin[b + 1]);
    }
    if (ellipsoids) {
#pragma omp for schedule(static)
      for (int b = 0; b < count; ++b) {
        frame_ellipsoids(p, s.ellipsoid_frames, blocks.particle_begin[b], blocks.particle_begin[b + 1]);
      }
    }
    const auto force_block = [&](int b) {
      for (Slot i = blocks.particle_begin[b]; i < blocks.particle_begin[b + 1]; ++i) {
        p.force[i] = Vec<Dim>::Zero();
        p.moment[i] = Space<Dim>::zero_spin();
      }
      pair_fn(in, p, s.contacts.pairs, blocks, b, energies[b], nullptr);
      wall_fn(in, p, s.contacts.walls, blocks, b, energies[b], wall_sums.data() + static_cast<std::size_t>(b) * walls);
    };
    // Round particles: each thread keeps the same run of blocks every step,
    // about the particles it moves (motion.cpp's static blocks), so their
    // positions and force sums stay in its core's cache. Handed out
    // dynamically, blocks changed cores from step to step and their data
    // crossed between cores every step, which costs as much as the rows
    // where a cache line's round trip between cores is slow (docs/PERFORMANCE.md).
    // Shaped particles' rows cost microseconds each: there balance counts more.
    if (shaped) {
#pragma omp for schedule(dynamic, 1)
      for (int b = 0; b < count; ++b) force_block(b);
    } else {
#pragma omp for schedule(static)
      for (int b = 0; b < count; ++b) force_block(b);
    }
    // The shares set aside for each block, added in row order. Their
    // particles' sums lie anywhere in the block, out of the core's caches
    // on large beds: each is fetched 16 shares ahead (100k, one thread:
    // 1.013 side by side; 10k 1.001; docs/PERFORMANCE.md, item 23).
    constexpr std::int32_t kAhead = 16;
#pragma omp for schedule(static)
    for (int b = 0; b < count; ++b) {
      const std::int32_t group_end = blocks.deferred_begin[b + 1];
      for (std::int32_t k = blocks.deferred_begin[b]; k < group_end; ++k) {
        if (k + kAhead < group_end) {
          const Slot ahead = blocks.deferred_particle[k + kAhead];
          fetch_line(&p.force[ahead]);
          fetch_line(&p.moment[ahead]);
        }
        const Slot i = blocks.deferred_particle[k];
        p.force[i] += blocks.deferred_force[k];
        p.moment[i] += blocks.deferred_moment[k];
      }
    }
  }
  if (kPass == Pass::kAdvance && blocks.near_stale) {
    blocks.near_stale = false;
    s.near_slack = near_margin(s);
    ++s.profile.near_sortings;
    s.profile.near_rows = 0;
    for (const std::int32_t kept : blocks.near_count) s.profile.near_rows += static_cast<std::uint64_t>(kept);
  }
  Walls<Dim>& w = s.walls;
  std::fill(w.force.begin(), w.force.end(), Vec<Dim>::Zero());
  std::fill(w.moment.begin(), w.moment.end(), Space<Dim>::zero_spin());
  std::fill(w.normal_force.begin(), w.normal_force.end(), 0.0);
  std::fill(w.contacts.begin(), w.contacts.end(), 0);
  std::fill(w.normal_force_arm.begin(), w.normal_force_arm.end(), zero_eccentricity<Dim>());
  ContactEnergy total;
  for (int b = 0; b < count; ++b) {
    total += energies[b];
    for (int k = 0; k < walls; ++k) {
      const WallSum<Dim>& sum = wall_sums[static_cast<std::size_t>(b) * walls + k];
      w.force[k] += sum.force;
      w.moment[k] += sum.moment;
      w.normal_force[k] += sum.normal_force;
      w.contacts[k] += sum.contacts;
      w.normal_force_arm[k] += sum.normal_force_arm;
    }
  }
  return total;
}

template <int Dim>
ContactRecordT<Dim> to_record(const RowResult<Dim>& c, ParticleId first, std::uint64_t formed_cycle) {
  ContactRecordT<Dim> record;
  record.first = first;
  record.point = c.geometry.point;
  record.normal = c.geometry.normal;
  record.overlap = c.geometry.overlap;
  record.normal_force = c.forces.normal;
  record.shear_force = reported_shear(c.forces.shear);
  record.tangential_force = -shear_vector(c.forces.shear, c.geometry.normal);
  record.normal_damping = c.forces.normal_damping;
  record.shear_damping = reported_shear(c.forces.shear_damping);
  record.sliding = c.sliding;
  record.formed_cycle = formed_cycle;
  record.force = c.force;
  return record;
}

// Calls visit(report) for every touching row as the last pass left it;
// `only_pair_row` limits the visit to one pair row (a lookup), `only_wall`
// to the rows of one wall.
template <int Dim, typename Visit>
void visit_rows(const WorldState<Dim>& s, std::optional<std::size_t> only_pair_row, Visit visit,
                std::optional<WallId> only_wall = std::nullopt) {
  std::vector<EllipsoidFrame> frames;
  if (s.shape == ShapeKind::kEllipsoid) {
    frames.resize(s.particles.size());
    frame_ellipsoids(s.particles, frames, 0, static_cast<std::int64_t>(frames.size()));
  }
  const PassInputs<Dim> in = inputs(s, current_context(s), frames);
  ContactEnergy unused;
  const Particles<Dim>& p = s.particles;
  auto report = [&](bool wall, std::size_t r, const RowResult<Dim>& c, const ContactRows<Dim>& rows) {
    RowReport<Dim> out{wall,
                       r,
                       to_record(c, p.id[rows.first[r]], rows.formed_cycle[r]),
                       c.forces.shear_damping,
                       c.force,
                       c.moment_first,
                       c.moment_second};
    if (wall) {
      out.record.second_wall = WallId{rows.second[r]};
    } else {
      out.record.second_particle = p.id[rows.second[r]];
    }
    visit(out);
  };
  with_shape<Dim>(s.shape, [&]<typename Shape>() {
    // The touching rows of one table in [begin, end) that `wanted` keeps.
    const auto visit_table = [&]<typename Body>(ContactLaw law, const ContactRows<Dim>& rows, std::size_t begin,
                                                std::size_t end, auto wanted) {
      with_law(law, [&]<typename Law>() {
        for (std::size_t r = begin; r < end; ++r) {
          if (!rows.touching(r) || !wanted(r)) continue;
          const RowResult<Dim> c = contact_row<Pass::kEvaluate, false, Law, Shape, Body>(in, rows, r, unused);
          if (c.touching) report(Body::kWall, r, c, rows);
        }
      });
    };
    if (!only_wall) {
      const std::size_t begin = only_pair_row.value_or(0);
      const std::size_t end = only_pair_row ? begin + 1 : s.contacts.pairs.size();
      visit_table.template operator()<ParticleBody<Dim>>(s.pair_law, s.contacts.pairs, begin, end,
                                                         [](std::size_t) { return true; });
    }
    if (only_pair_row) return;
    const ContactRows<Dim>& walls = s.contacts.walls;
    visit_table.template operator()<WallBody<Dim>>(s.wall_law, walls, 0, walls.size(), [&](std::size_t r) {
      return !only_wall || walls.second[r] == only_wall->value();
    });
  });
}

}  // namespace

template <int Dim>
ContactEnergy advance_contacts(WorldState<Dim>& state, const StepContext& step) {
  return run_pass<Pass::kAdvance>(state, step);
}

template <int Dim>
void evaluate_contacts(WorldState<Dim>& state) {
  run_pass<Pass::kEvaluate>(state, current_context(state));
}

template <int Dim>
void visit_touching_rows(const WorldState<Dim>& state, const std::function<void(const RowReport<Dim>&)>& visit) {
  visit_rows(state, std::nullopt, visit);
}

template <int Dim>
void visit_touching_contacts(const WorldState<Dim>& state,
                             const std::function<void(const ContactRecordT<Dim>&)>& visit) {
  visit_rows(state, std::nullopt, [&](const RowReport<Dim>& r) { visit(r.record); });
}

template <int Dim>
std::vector<ContactRecordT<Dim>> report_contacts(const WorldState<Dim>& state) {
  std::vector<ContactRecordT<Dim>> records;
  std::size_t touching = 0;
  for (const std::uint8_t f : state.contacts.pairs.flags) touching += (f & kTouching) != 0;
  for (const std::uint8_t f : state.contacts.walls.flags) touching += (f & kTouching) != 0;
  records.reserve(touching);
  visit_rows(state, std::nullopt, [&](const RowReport<Dim>& r) { records.push_back(r.record); });
  return records;
}

template <int Dim>
std::vector<ContactRecordT<Dim>> report_wall_contacts(const WorldState<Dim>& state, WallId wall) {
  std::vector<ContactRecordT<Dim>> records;
  visit_rows(
      state, std::nullopt, [&](const RowReport<Dim>& r) { records.push_back(r.record); }, wall);
  return records;
}

template <int Dim>
std::optional<ContactRecordT<Dim>> report_pair_contact(const WorldState<Dim>& state, ParticleId a, ParticleId b) {
  const Particles<Dim>& p = state.particles;
  if (!p.contains(a) || !p.contains(b) || a == b) return std::nullopt;
  // Rows are oriented from the lower id and sorted by slot.
  const ContactKey key{p.slot_of(std::min(a, b)), p.slot_of(std::max(a, b))};
  const ContactRows<Dim>& rows = state.contacts.pairs;
  const auto begin = std::lower_bound(rows.first.begin(), rows.first.end(), key.first) - rows.first.begin();
  for (auto r = static_cast<std::size_t>(begin); r < rows.size() && rows.first[r] == key.first; ++r) {
    if (rows.second[r] != key.second) continue;
    std::optional<ContactRecordT<Dim>> found;
    visit_rows(state, r, [&](const RowReport<Dim>& report) { found = report.record; });
    return found;
  }
  return std::nullopt;
}

template ContactEnergy advance_contacts(WorldState<2>&, const StepContext&);
template ContactEnergy advance_contacts(WorldState<3>&, const StepContext&);
template void evaluate_contacts(WorldState<2>&);
template void evaluate_contacts(WorldState<3>&);
template void visit_touching_rows(const WorldState<2>&, const std::function<void(const RowReport<2>&)>&);
template void visit_touching_rows(const WorldState<3>&, const std::function<void(const RowReport<3>&)>&);
template void visit_touching_contacts(const WorldState<2>&, const std::function<void(const ContactRecordT<2>&)>&);
template void visit_touching_contacts(const WorldState<3>&, const std::function<void(const ContactRecordT<3>&)>&);
template std::vector<ContactRecordT<2>> report_contacts(const WorldState<2>&);
template std::vector<ContactRecordT<3>> report_contacts(const WorldState<3>&);
template std::vector<ContactRecordT<2>> report_wall_contacts(const WorldState<2>&, WallId);
template std::vector<ContactRecordT<3>> report_wall_contacts(const WorldState<3>&, WallId);
template std::optional<ContactRecordT<2>> report_pair_contact(const WorldState<2>&, ParticleId, ParticleId);
template std::optional<ContactRecordT<3>> report_pair_contact(const WorldState<3>&, ParticleId, ParticleId);

}  // namespace dem
