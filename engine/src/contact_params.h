// Contact parameters resolved once per pair of materials, so the force loop
// looks them up instead of branching on materials per contact.
#pragma once

#include <vector>

#include "dem/definitions.h"
#include "law_list.h"

namespace dem {

struct ContactParams {
  bool defined = false;
  ContactLaw law = ContactLaw::kLinear;
  double friction = 0.0;  // tan(phi_mu) of the pair (eq. 19)
  double cohesion = 0.0;  // c of the pair (eq. 19)
  // Linear laws
  double normal_stiffness = 0.0;  // k_n
  double shear_stiffness = 0.0;   // k_s
  double normal_viscosity = 0.0;  // BALL: c_n = beta k_n (eq. 28)
  double shear_viscosity = 0.0;   // BALL: c_s = beta k_s (eq. 28)
  // Miyata eq. 17 without the effective mass: c_n = restitution_viscosity sqrt(m*).
  double restitution_viscosity = 0.0;
  // Hertz laws
  double contact_modulus = 0.0;  // E* (Randall 3.6, 4.7)
  double shear_modulus = 0.0;    // G* (Randall 4.8-4.10)
  double damping_ratio = 0.0;    // beta, fraction of critical (Randall 4.13)
  // The same fraction on the tangential stiffness (Randall 4.19), 0 when
  // the model has no tangential dashpot.
  double tangential_damping_ratio = 0.0;
  // The dashpots' coefficients over sqrt(m* a): both stiffnesses grow as the
  // contact radius a (2 E* a, 8 G* a), so 2 beta sqrt(m* k) (Randall 4.13,
  // 4.19) is 2 beta sqrt(2 E*) sqrt(m* a) and 2 beta sqrt(8 G*) sqrt(m* a),
  // and one root per contact serves both.
  double normal_dashpot = 0.0;
  double tangential_dashpot = 0.0;
  // Rolling resistance (rolling_resistance.h): mu_r and eta_r.
  double rolling_friction = 0.0;
  double rolling_damping_ratio = 0.0;

  bool operator==(const ContactParams&) const = default;
};

// What every pair of materials resolves whatever its law: friction and
// cohesion (eq. 19), the linear springs and BALL's dashpots (eqs. 16-17,
// 28), the pair's E* and G* (Randall 3.6, 4.8-4.10), rolling resistance.
// Every law's set holds them, so sets compare field by field
// (parameter_sets.h) as the materials differ.
ContactParams common_params(const MaterialDef& a, const MaterialDef& b, const ContactModelDef& model,
                            const DampingDef& damping);

// The parameters of a pair of materials a and b under `model`: the common
// ones, then the law's own (Law::resolve) for a law of List.
template <typename List>
ContactParams resolve_params(const MaterialDef& a, const MaterialDef& b, const ContactModelDef& model,
                             const DampingDef& damping) {
  ContactParams p = common_params(a, b, model, damping);
  with_law_of<List>(model.law, [&]<typename Law>() { Law::resolve(p, model); });
  return p;
}

// How a table resolves a pair of materials (resolve_params of a list of laws).
using ResolvePair = ContactParams (*)(const MaterialDef& a, const MaterialDef& b, const ContactModelDef& model,
                                      const DampingDef& damping);

// A square table indexed by (material_a, material_b), symmetric. Indexed
// by the materials' plain values: the force pass looks it up per contact
// from Particles::material.
class ContactParamTable {
 public:
  ContactParamTable() = default;
  // Each pair under the engine's laws (law_dispatch.h), or under `resolve`.
  ContactParamTable(const std::vector<MaterialDef>& materials, const std::vector<ContactModelDef>& models,
                    const DampingDef& damping);
  ContactParamTable(const std::vector<MaterialDef>& materials, const std::vector<ContactModelDef>& models,
                    const DampingDef& damping, ResolvePair resolve);
  const ContactParams& operator()(std::int32_t a, std::int32_t b) const { return params_[a * count_ + b]; }
  int count() const { return count_; }  // materials

 private:
  int count_ = 0;
  std::vector<ContactParams> params_;
};

// Hertz damping ratio beta equivalent to a coefficient of restitution e.
double damping_ratio_from_restitution(double restitution);

}  // namespace dem
