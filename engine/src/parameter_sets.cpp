#include "parameter_sets.h"

#include <algorithm>

namespace dem {

RowSets row_sets(const ContactParamTable& table, const std::vector<std::int32_t>& first,
                 const std::vector<std::int32_t>& second) {
  RowSets rows;
  const int materials = table.count();
  rows.set_of.assign(static_cast<std::size_t>(materials) * materials, 0);
  for (const std::int32_t a : first) {
    for (const std::int32_t b : second) {
      const ContactParams& params = table(a, b);
      const auto known = std::find(rows.sets.begin(), rows.sets.end(), params);
      const auto s = static_cast<std::int32_t>(known - rows.sets.begin());
      if (known == rows.sets.end()) rows.sets.push_back(params);
      rows.set_of[static_cast<std::size_t>(a) * materials + b] = s;
    }
  }
  return rows;
}

FewSets few_sets(const RowSets& sets) {
  FewSets few;
  for (int s = 0; s < kFewSets; ++s) {
    few.set[s] = sets.sets[std::min<std::size_t>(static_cast<std::size_t>(s), sets.sets.size() - 1)];
  }
  return few;
}

}  // namespace dem
