#include "contact_params.h"

#include <algorithm>

namespace dem {

ContactParamTable::ContactParamTable(const std::vector<MaterialDef>& materials,
                                     const std::vector<ContactModelDef>& models, const DampingDef& damping)
    : count_(static_cast<int>(materials.size())), params_(materials.size() * materials.size()) {
  auto resolve = [&](MaterialId a, MaterialId b, const ContactModelDef& model) {
    ContactParams p;
    p.defined = true;
    p.normal_stiffness = model.linear.normal_stiffness;
    p.shear_stiffness = model.linear.shear_stiffness;
    // Cundall & Strack eq. 19 and footnote 1: the smaller friction and cohesion of the two.
    p.friction = model.friction.value_or(std::min(materials[a].friction, materials[b].friction));
    p.cohesion = model.cohesion.value_or(std::min(materials[a].cohesion, materials[b].cohesion));
    p.normal_viscosity = damping.contact_beta * p.normal_stiffness;  // eq. 28
    p.shear_viscosity = damping.contact_beta * p.shear_stiffness;
    params_[a * count_ + b] = p;
    params_[b * count_ + a] = p;
  };
  // The default model first, then the named pairs override it.
  for (const ContactModelDef& model : models) {
    if (model.material_a != kInvalidId) continue;
    for (MaterialId a = 0; a < count_; ++a)
      for (MaterialId b = a; b < count_; ++b) resolve(a, b, model);
  }
  for (const ContactModelDef& model : models) {
    if (model.material_a == kInvalidId) continue;
    resolve(model.material_a, model.material_b, model);
  }
}

}  // namespace dem
