// One contact law serves all particle-particle contacts of a world and one
// all particle-wall contacts (they may differ), so the force passes choose
// each once, not per contact. Which laws a world's materials resolve to.
#pragma once

#include <span>
#include <vector>

#include "contact_params.h"
#include "dem/definitions.h"

namespace dem {

struct WorldLaws {
  ContactLaw pair = ContactLaw::kLinear;
  ContactLaw wall = ContactLaw::kLinear;
};

// Every pair of materials that can touch needs a contact law, and all
// particle-particle pairs (and all particle-wall pairs) must share one.
// Hertz laws need the elastic constants of the particles' materials.
// Throws DefinitionError naming the materials otherwise.
WorldLaws resolve_contact_laws(const std::vector<MaterialDef>& materials, const ContactParamTable& params,
                               std::span<const std::int32_t> particle_materials,
                               std::span<const std::int32_t> wall_materials);

}  // namespace dem
