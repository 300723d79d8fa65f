// Contacts as a numpy structured array, one row per contact (the fields of
// protocol::ContactEntry; vectors as (3,) sub-arrays, z = 0 in 2D).
#pragma once

#include <pybind11/numpy.h>

#include <vector>

#include "dem/protocol/messages.h"

namespace dem::python {

// One row of the array; its numpy dtype is registered by register_contact_dtype.
struct ContactRow {
  std::int32_t first;
  std::int32_t second_particle;  // -1 for a wall contact
  std::int32_t second_wall;      // -1 for a particle-particle contact
  double point[3];               // m
  double normal[3];              // unit, from the first body towards the second
  double overlap;                // m
  double normal_force;           // N (per unit depth in 2D)
  double shear_force;            // N: signed along t in 2D, the magnitude in 3D
  double normal_damping;         // N
  double shear_damping;          // N
  bool sliding;
};

void register_contact_dtype();
pybind11::dtype contact_dtype();
pybind11::array contact_array(const std::vector<protocol::ContactEntry>& contacts);

}  // namespace dem::python
