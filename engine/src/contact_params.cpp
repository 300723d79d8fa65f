#include "contact_params.h"

#include <algorithm>
#include <cmath>
#include <numbers>

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

ContactParamTable::ContactParamTable(const std::vector<MaterialDef>& materials,
                                     const std::vector<ContactModelDef>& models, const DampingDef& damping)
    : count_(static_cast<int>(materials.size())), params_(materials.size() * materials.size()) {
  auto resolve = [&](std::int32_t a, std::int32_t b, const ContactModelDef& model) {
    ContactParams p;
    p.defined = true;
    p.law = model.law;
    // Cundall & Strack eq. 19 and footnote 1: the smaller friction and cohesion of the two.
    p.friction = model.friction.value_or(std::min(materials[a].friction, materials[b].friction));
    p.cohesion = model.cohesion.value_or(std::min(materials[a].cohesion, materials[b].cohesion));
    p.normal_stiffness = model.linear.normal_stiffness;
    p.shear_stiffness = model.linear.shear_stiffness;
    p.normal_viscosity = damping.contact_beta * p.normal_stiffness;  // eq. 28
    p.shear_viscosity = damping.contact_beta * p.shear_stiffness;
    if (model.law == ContactLaw::kLinearRestitution && model.restitution < 1.0) {
      // Miyata eq. 17: c_n = 2 ln(1/e) sqrt(k_n m* / (pi^2 + ln^2(1/e))).
      const double log_inverse = std::log(1.0 / model.restitution);
      p.restitution_viscosity =
          2.0 * log_inverse *
          std::sqrt(p.normal_stiffness / (std::numbers::pi * std::numbers::pi + log_inverse * log_inverse));
    }
    const double c = compliance(materials[a]) + compliance(materials[b]);
    const double g = shear_compliance(materials[a]) + shear_compliance(materials[b]);
    p.contact_modulus = c > 0.0 ? 1.0 / c : 0.0;
    p.shear_modulus = g > 0.0 ? 1.0 / g : 0.0;
    p.damping_ratio =
        model.hertz.restitution ? damping_ratio_from_restitution(*model.hertz.restitution) : model.hertz.damping_ratio;
    p.tangential_damping_ratio = model.hertz.tangential ? p.damping_ratio : 0.0;
    p.normal_dashpot = 2.0 * p.damping_ratio * std::sqrt(2.0 * p.contact_modulus);
    p.tangential_dashpot = 2.0 * p.tangential_damping_ratio * std::sqrt(8.0 * p.shear_modulus);
    p.rolling_friction = model.rolling.friction;
    p.rolling_damping_ratio = model.rolling.damping_ratio;
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
