// Validation of a case's contact models: each law's numbers, one model per
// pair of materials, a model for every pair that can touch, one law for
// each kind of contact, and the elastic constants the Hertz laws need.
#pragma once

#include <set>
#include <string>

#include "case_names.h"
#include "dem/case.pb.h"
#include "problem_list.h"

namespace dem::io {

// What the contact models are checked against: the materials by name, and
// which of them particles and walls are made of.
struct MaterialUses {
  const NameIndex& materials;
  const std::set<std::string>& particles;
  const std::set<std::string>& walls;
};

void check_contact_models(const proto::Case& c, const MaterialUses& uses, ProblemList& problems);

}  // namespace dem::io
