// Picks a contact law's policy type from its enum, once per pass.
#pragma once

#include "dem/definitions.h"
#include "hertz_laws.h"
#include "linear_law.h"
#include "restitution_law.h"

namespace dem {

// Calls pass.template operator()<Law>() with the law's type: one branch
// per pass, none per contact.
template <typename Pass>
void with_law(ContactLaw law, Pass&& pass) {
  switch (law) {
    case ContactLaw::kLinear:
      pass.template operator()<LinearLaw>();
      break;
    case ContactLaw::kLinearRestitution:
      pass.template operator()<RestitutionLaw>();
      break;
    case ContactLaw::kHertzMindlin:
      pass.template operator()<HertzMindlinLaw>();
      break;
    case ContactLaw::kHertzLinearTangential:
      pass.template operator()<HertzLinearTangentialLaw>();
      break;
  }
}

}  // namespace dem
