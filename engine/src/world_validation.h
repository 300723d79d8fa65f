// Checks a world definition before anything is built from it: each
// problem is a DefinitionError naming the item and what is wrong.
#pragma once

#include <string>

#include "dem/definitions.h"

namespace dem {

// Throws DefinitionError(message) unless ok.
void check(bool ok, const std::string& message);

// The name of a material in quotes, for messages.
std::string quoted(const MaterialDef& material);

void check_damping(const DampingDef& damping);

template <int Dim>
void validate_world(const WorldDefT<Dim>& def);

}  // namespace dem
