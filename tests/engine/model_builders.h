// Small builders the engine tests share.
#pragma once

#include "dem/definitions.h"

namespace dem::testing {

// A BALL linear contact model (Cundall & Strack eqs. 16-17) for every pair
// of materials, or for one pair when materials are given.
inline ContactModelDef linear_model(double normal_stiffness, double shear_stiffness, MaterialId a = kInvalidId,
                                    MaterialId b = kInvalidId) {
  ContactModelDef model;
  model.material_a = a;
  model.material_b = b;
  model.linear = {normal_stiffness, shear_stiffness};
  return model;
}

}  // namespace dem::testing
