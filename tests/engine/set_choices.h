// Which way the batched passes read the contact parameters of a world
// built from a definition: the engine tests' view into parameter_sets.h,
// kept apart from model_builders.h, which tests outside the engine share.
#pragma once

#include <cstdint>
#include <set>
#include <vector>

#include "parameter_sets.h"

namespace dem::testing {

// How the batched passes' law loops read the parameters of the pair rows
// and of the wall rows of a world built from `def` (parameter_sets.h).
struct SetChoices {
  SetChoice pairs, walls;
};
template <typename Def>
SetChoices set_choices(const Def& def) {
  const ContactParamTable table(def.materials, def.contact_models, def.damping);
  std::set<std::int32_t> particle_set, wall_set;
  for (const auto& p : def.particles) particle_set.insert(p.material.value());
  for (const auto& w : def.walls) wall_set.insert(w.material.value());
  const std::vector<std::int32_t> particles(particle_set.begin(), particle_set.end());
  const std::vector<std::int32_t> walls(wall_set.begin(), wall_set.end());
  return {row_sets(table, particles, particles).choice(), row_sets(table, particles, walls).choice()};
}

}  // namespace dem::testing
