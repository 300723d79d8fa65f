// Element-test control of a box of walls (dem/definitions.h, BoxControlT):
// what the box measures and the velocities it gives its walls each cycle.
#pragma once

#include <string>

#include "dem/definitions.h"
#include "dem/measures.h"
#include "walls.h"

namespace dem {

// The box as the last force pass left it (targets from those stresses).
template <int Dim>
BoxMeasureT<Dim> measure_box(const Walls<Dim>& walls, const BoxControlT<Dim>& box);

// The velocity of each of the box's walls for the next step: strain rates
// and servos on the stresses of the last force pass.
template <int Dim>
void set_box_velocities(const Walls<Dim>& walls, const BoxControlT<Dim>& box, std::vector<Vec<Dim>>& velocity);

// The continuum field of a box with `continuum` for the next step (Randall
// 4.5.2, eqs. 4.43-4.44): each axis's rate from the speed its walls are
// given (set_box_velocities), about the box's centre.
template <int Dim>
ContinuumFieldT<Dim> box_continuum(const Walls<Dim>& walls, const BoxControlT<Dim>& box);

// The distance between each axis's two walls, m.
template <int Dim>
Vec<Dim> box_extent(const Walls<Dim>& walls, const BoxControlT<Dim>& box);

// Throws DefinitionError naming the field when the control makes no sense
// for these walls (unknown, repeated or removed walls, walls that do not
// face along their axis, a stress control without gain, a path without
// axes to follow or to set).
template <int Dim>
void check_box_control(const BoxControlT<Dim>& box, const std::vector<WallDefT<Dim>>& walls);

// A continuum field carries the particles across the box: a periodic cell,
// which does not deform, has none (DefinitionError).
template <int Dim>
void check_box_continuum(const BoxControlT<Dim>& box, const PeriodicDefT<Dim>& periodic);

}  // namespace dem
