// The engine's contact laws, one entry each: the dispatch from a law's enum
// value to its type, its name and its traits follow from this list
// (law_list.h). A new law is its file and its entry here (and its value of
// ContactLaw and the schema's).
#pragma once

#include "hertz_laws.h"
#include "law_list.h"
#include "linear_law.h"
#include "restitution_law.h"

namespace dem {

using ContactLaws = LawList<LinearLaw, RestitutionLaw, HertzMindlinLaw, HertzLinearTangentialLaw>;
static_assert(distinct_laws(ContactLaws{}), "two laws of the list share a ContactLaw value or a name");

// Calls pass.template operator()<Law>() with the law's type: one branch
// per pass, none per contact.
// Returns false for a value no law has.
template <typename Pass>
bool with_law(ContactLaw law, Pass&& pass) {
  return with_law_of<ContactLaws>(law, pass);
}

}  // namespace dem
