// Errors raised at the engine's API. Programmer errors are asserts; a bad
// definition (for example from a case file) is a DefinitionError naming the item.
#pragma once

#include <stdexcept>
#include <string>

namespace dem {

class DefinitionError : public std::invalid_argument {
 public:
  explicit DefinitionError(const std::string& what) : std::invalid_argument(what) {}
};

}  // namespace dem
