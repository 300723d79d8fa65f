// Names a case refers to (materials, walls) and how validation messages
// spell them: quoted, and listed when a reference does not resolve.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>

#include "problem_list.h"

namespace dem::io {

// Each name with the index of its first definition.
using NameIndex = std::map<std::string, int, std::less<>>;

inline std::string in_quotes(std::string_view name) { return '"' + std::string(name) + '"'; }

// "(the case defines "a", "b")", so an unknown name comes with the known ones.
inline std::string defined_names(const NameIndex& names) {
  if (names.empty()) return "(the case defines none)";
  std::string text = "(the case defines ";
  for (const auto& [name, index] : names) {
    if (text.back() != ' ') text += ", ";
    text += in_quotes(name);
  }
  return text + ')';
}

// The material's index, or -1 after reporting why there is none.
inline int find_material(ProblemList& problems, const NameIndex& materials, const std::string& path,
                         const std::string& name) {
  if (name.empty()) {
    problems.add(path, "must name a material " + defined_names(materials));
    return -1;
  }
  const auto found = materials.find(name);
  if (found == materials.end()) {
    problems.add(path, "unknown material " + in_quotes(name) + ' ' + defined_names(materials));
    return -1;
  }
  return found->second;
}

// The wall's index, or -1 after reporting why there is none.
inline int find_wall(ProblemList& problems, const NameIndex& walls, const std::string& path, const std::string& name) {
  if (name.empty()) {
    problems.add(path, "must name a wall " + defined_names(walls));
    return -1;
  }
  const auto found = walls.find(name);
  if (found == walls.end()) {
    problems.add(path, "unknown wall " + in_quotes(name) + ' ' + defined_names(walls));
    return -1;
  }
  return found->second;
}

}  // namespace dem::io
