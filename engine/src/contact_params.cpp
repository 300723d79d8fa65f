#include "contact_params.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "law_dispatch.h"

namespace dem {

namespace {

// 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Randall 3.6; Johnson); a body
// with E = 0 is rigid and adds nothing.
double compliance(const MaterialDef& m) {
  return m.youngs_modulus > 0.0 ? (1.0 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus : 0.0;
}

// 1/G* = (2 - nu1)/G1 + (2 - nu2)/G2 with G = E / (2 (1 + nu)) (Randall 4.8-4.10).
double shear_compliance(const MaterialDef& m) {
  return m.youngs_modulus > 0.0 ? 2.0 * (2.0 - m.poisson_ratio) * (1.0 + m.poisson_ratio) / m.youngs_modulus : 0.0;
}

}  // namespace

double damping_ratio_from_restitution(double restitution) {
  const double log_e = std::log(restitution);
  return std::sqrt(5.0 / 6.0) * -log_e / std::sqrt(log_e * log_e + std::numbers::pi * std::numbers::pi);
}

ContactParams common_params(const MaterialDef& a, const MaterialDef& b, const ContactModelDef& model,
                            const DampingDef& damping) {
  ContactParams p;
  p.defined = true;
  p.law = model.law;
  // Cundall & Strack eq. 19 and footnote 1: the smaller friction and cohesion of the two.
  p.friction = model.friction.value_or(std::min(a.friction, b.friction));
  p.cohesion = model.cohesion.value_or(std::min(a.cohesion, b.cohesion));
  p.normal_stiffness = model.linear.normal_stiffness;
  p.shear_stiffness = model.linear.shear_stiffness;
  p.normal_viscosity = damping.contact_beta * p.normal_stiffness;  // eq. 28
  p.shear_viscosity = damping.contact_beta * p.shear_stiffness;
  const double c = compliance(a) + compliance(b);
  const double g = shear_compliance(a) + shear_compliance(b);
  p.contact_modulus = c > 0.0 ? 1.0 / c : 0.0;
  p.shear_modulus = g > 0.0 ? 1.0 / g : 0.0;
  p.rolling_friction = model.rolling.friction;
  p.rolling_damping_ratio = model.rolling.damping_ratio;
  return p;
}

ContactParamTable::ContactParamTable(const std::vector<MaterialDef>& materials,
                                     const std::vector<ContactModelDef>& models, const DampingDef& damping)
    : ContactParamTable(materials, models, damping, &resolve_params<ContactLaws>) {}

ContactParamTable::ContactParamTable(const std::vector<MaterialDef>& materials,
                                     const std::vector<ContactModelDef>& models, const DampingDef& damping,
                                     ResolvePair resolve_pair)
    : count_(static_cast<int>(materials.size())), params_(materials.size() * materials.size()) {
  auto resolve = [&](std::int32_t a, std::int32_t b, const ContactModelDef& model) {
    const ContactParams p = resolve_pair(materials[a], materials[b], model, damping);
    params_[a * count_ + b] = p;
    params_[b * count_ + a] = p;
  };
  // The default model first, then the named pairs override it.
  for (const ContactModelDef& model : models) {
    if (model.material_a != kInvalidId) continue;
    for (std::int32_t a = 0; a < count_; ++a)
      for (std::int32_t b = a; b < count_; ++b) resolve(a, b, model);
  }
  for (const ContactModelDef& model : models) {
    if (model.material_a == kInvalidId) continue;
    resolve(model.material_a.value(), model.material_b.value(), model);
  }
}

}  // namespace dem
