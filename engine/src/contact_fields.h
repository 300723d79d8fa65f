// The contact table's side of the one field list (for_each_contact_field in
// dem/snapshot.h): which columns a table keeps, and the history fields of
// one row walked in list order.
#pragma once

#include <cstddef>
#include <type_traits>

#include "contact_table.h"
#include "dem/snapshot.h"

namespace dem {

// Whether a table with these columns holds a field of `column`.
inline bool keeps(const ContactColumns& columns, ContactColumn column) {
  switch (column) {
    case ContactColumn::kNone:
      return false;
    case ContactColumn::kAlways:
      return true;
    case ContactColumn::kNormalForce:
      return columns.normal_force;
    case ContactColumn::kMindlin:
      return columns.mindlin;
    case ContactColumn::kSearch:
      return columns.search;
    case ContactColumn::kDashpot:
      return columns.dashpot;
    case ContactColumn::kRolling:
      return columns.rolling;
  }
  return false;
}

// Calls visit(info, field, value) for every history field the table keeps,
// in list order: field(c) is the field of a contact snapshot, value the
// same quantity in row r (const when rows is).
template <int Dim, typename Rows, typename Visit>
void for_each_kept_field(Rows& rows, std::size_t r, Visit&& visit) {
  for_each_contact_field<Dim>([&](const ContactFieldInfo& info, auto field, auto row) {
    if constexpr (!std::is_same_v<decltype(row), NoRow>) {
      if (keeps(rows.columns, info.column)) visit(info, field, row(rows, r));
    }
  });
}

}  // namespace dem
