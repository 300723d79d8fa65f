// Small builders the engine tests share.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "dem/definitions.h"

namespace dem::testing {

// A BALL linear contact model (Cundall & Strack eqs. 16-17) for every pair
// of materials, or for one pair when materials are given.
inline ContactModelDef linear_model(double normal_stiffness, double shear_stiffness, MaterialId a = kInvalidId,
                                    MaterialId b = kInvalidId) {
  ContactModelDef model;
  model.material_a = a;
  model.material_b = b;
  model.linear = {normal_stiffness, shear_stiffness};
  return model;
}

// Spreads a bed of one material (0, under linear laws) over several with
// the same physics: the walls take a copy of material 0, and particle i
// material i % particle_materials, where material 0 stays and the others
// are copies whose Young's modulus grows by modulus_step each. The linear
// laws do not read the modulus: with a step of 0 every row resolves to the
// one parameter set of the bed, with any other step the rows' sets differ
// (parameter_sets.h) and each row finds its own, for the same forces.
template <typename Def>
void spread_materials(Def& def, int particle_materials, double modulus_step) {
  const MaterialDef base = def.materials.at(0);
  def.materials.resize(1);
  const auto add = [&](double modulus) {
    MaterialDef copy = base;
    copy.name += '_';
    copy.name += std::to_string(def.materials.size());
    copy.youngs_modulus = modulus;
    def.materials.push_back(copy);
    return MaterialId{static_cast<std::int32_t>(def.materials.size() - 1)};
  };
  const MaterialId wall = add(base.youngs_modulus);
  for (auto& w : def.walls) w.material = wall;
  std::vector<MaterialId> kinds{MaterialId{0}};
  for (int k = 1; k < particle_materials; ++k) kinds.push_back(add(base.youngs_modulus + k * modulus_step));
  for (std::size_t i = 0; i < def.particles.size(); ++i) def.particles[i].material = kinds[i % kinds.size()];
}

// Gives the particles of `def` the materials `kinds` in turn (particle i
// kinds[i % 3]) and each pair of them its own linear model, the stiffnesses
// k_n, k_s times 1 + (x + 2 y) / 10 for kinds x <= y: six distinct sets
// of particle pairs.
template <typename Def>
void three_kinds_with_pair_models(Def& def, const MaterialId (&kinds)[3], double normal_stiffness,
                                  double shear_stiffness) {
  for (std::size_t i = 0; i < def.particles.size(); ++i) def.particles[i].material = kinds[i % 3];
  for (int x = 0; x < 3; ++x) {
    for (int y = x; y < 3; ++y) {
      const double factor = 1.0 + 0.1 * (x + 2 * y);
      def.contact_models.push_back(
          linear_model(normal_stiffness * factor, shear_stiffness * factor, kinds[x], kinds[y]));
    }
  }
}

}  // namespace dem::testing
