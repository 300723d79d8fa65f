// Checks a world definition before anything is built from it: each
// problem is a DefinitionError naming the item and what is wrong.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "dem/definitions.h"
#include "periodic.h"

namespace dem {

// Throws DefinitionError(message) unless ok.
void check(bool ok, const std::string& message);

// The name of a material in quotes, for messages.
std::string quoted(const MaterialDef& material);

void check_damping(const DampingDef& damping);

template <int Dim>
void validate_world(const WorldDefT<Dim>& def);

// Nearest images are unique only while a period holds two interaction
// ranges: every repeating axis longer than twice (the largest diameter plus
// the contact tolerance).
template <int Dim>
void check_periodic_reach(const Periodic<Dim>& periodic, double max_radius, double contact_tolerance);

// The checks of a world's setters: a wall's new motion, the time step and a
// material's friction.
template <int Dim>
void check_wall_motion(const WallMotionT<Dim>& motion, WallId wall);
void check_time_step_fraction(double fraction);
void check_fixed_time_step(double seconds);
void check_friction(MaterialId material, std::size_t materials, double friction);
// The body forces a world or a stage sets: finite gravity; a centripetal
// field with a finite centre and an acceleration >= 0.
template <int Dim>
void check_body_force(const Vec<Dim>& gravity, const std::optional<CentripetalGravityT<Dim>>& centripetal);

}  // namespace dem
