// Contact parameters resolved once per pair of materials, so the force loop
// looks them up instead of branching on materials per contact.
#pragma once

#include <vector>

#include "dem/definitions.h"

namespace dem {

struct ContactParams {
  bool defined = false;
  double normal_stiffness = 0.0;  // k_n
  double shear_stiffness = 0.0;   // k_s
  double friction = 0.0;          // tan(phi_mu) of the pair (eq. 19)
  double cohesion = 0.0;          // c of the pair (eq. 19)
  double normal_viscosity = 0.0;  // c_n = beta k_n (eq. 28)
  double shear_viscosity = 0.0;   // c_s = beta k_s (eq. 28)
};

// A square table indexed by (material_a, material_b), symmetric.
class ContactParamTable {
 public:
  ContactParamTable() = default;
  ContactParamTable(const std::vector<MaterialDef>& materials, const std::vector<ContactModelDef>& models,
                    const DampingDef& damping);
  const ContactParams& operator()(MaterialId a, MaterialId b) const { return params_[a * count_ + b]; }

 private:
  int count_ = 0;
  std::vector<ContactParams> params_;
};

}  // namespace dem
