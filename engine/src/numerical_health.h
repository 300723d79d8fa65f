// The single checks behind HealthMonitorT (dem/health.h), each over the
// public state of a world; numerical_health.cpp composes them.
#pragma once

#include <optional>
#include <string>

#include "dem/health.h"

namespace dem::health {

// The first particle whose position or velocity is not finite, as text.
template <int Dim>
std::optional<std::string> non_finite_particle(const BasicWorld<Dim>& world);

// The contact overlapping most, relative to its smaller radius, if beyond `limit`.
template <int Dim>
std::optional<std::string> deepest_overlap(const BasicWorld<Dim>& world, double limit);

// Three significant digits, for messages.
std::string number(double value);

// Energy created: held and dissipated beyond what came in (the negated residual).
inline double created_energy(const EnergyBudget& e) { return -e.residual(); }

}  // namespace dem::health
