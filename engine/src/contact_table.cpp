#include "contact_table.h"

#include <algorithm>
#include <numeric>

namespace dem {

template <int Dim>
void gather_rows(ContactRows<Dim>& rows, const std::vector<std::int32_t>& from, const std::vector<ContactKey>& keys) {
  rows.for_each_column([&](auto& column) {
    using Array = std::decay_t<decltype(column)>;
    using T = typename Array::value_type;
    Array moved(from.size(), fresh<T>());
    for (std::size_t k = 0; k < from.size(); ++k) {
      if (from[k] >= 0) moved[k] = column[static_cast<std::size_t>(from[k])];
    }
    column.swap(moved);
  });
  // Fresh rows carry their keys.
  for (std::size_t k = 0; k < from.size(); ++k) {
    if (from[k] >= 0) continue;
    rows.first[k] = keys[k].first;
    rows.second[k] = keys[k].second;
  }
}

template <int Dim>
void merge_rows(ContactRows<Dim>& rows, const std::vector<ContactKey>& keys) {
  std::vector<std::int32_t> from(keys.size(), -1);
  std::size_t o = 0;
  const std::size_t old_size = rows.size();
  for (std::size_t k = 0; k < keys.size(); ++k) {
    while (o < old_size && ContactKey{rows.first[o], rows.second[o]} < keys[k]) ++o;
    if (o < old_size && rows.first[o] == keys[k].first && rows.second[o] == keys[k].second) {
      from[k] = static_cast<std::int32_t>(o);
    }
  }
  gather_rows(rows, from, keys);
}

template <int Dim>
void rename_slots(ContactRows<Dim>& rows, const std::vector<Slot>& renamed, bool pairs) {
  const std::size_t n = rows.size();
  std::vector<ContactKey> keys(n);
  std::vector<std::int32_t> order;
  order.reserve(n);
  for (std::size_t r = 0; r < n; ++r) {
    const Slot first = renamed[static_cast<std::size_t>(rows.first[r])];
    const std::int32_t second = pairs ? renamed[static_cast<std::size_t>(rows.second[r])] : rows.second[r];
    keys[r] = {first, second};
    if (first >= 0 && second >= 0) order.push_back(static_cast<std::int32_t>(r));
  }
  std::sort(order.begin(), order.end(), [&](std::int32_t a, std::int32_t b) { return keys[a] < keys[b]; });
  std::vector<ContactKey> sorted(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) sorted[k] = keys[static_cast<std::size_t>(order[k])];
  gather_rows(rows, order, sorted);
  for (std::size_t k = 0; k < sorted.size(); ++k) {
    rows.first[k] = sorted[k].first;
    rows.second[k] = sorted[k].second;
  }
}

template void gather_rows(ContactRows<2>&, const std::vector<std::int32_t>&, const std::vector<ContactKey>&);
template void gather_rows(ContactRows<3>&, const std::vector<std::int32_t>&, const std::vector<ContactKey>&);
template void merge_rows(ContactRows<2>&, const std::vector<ContactKey>&);
template void merge_rows(ContactRows<3>&, const std::vector<ContactKey>&);
template void rename_slots(ContactRows<2>&, const std::vector<Slot>&, bool);
template void rename_slots(ContactRows<3>&, const std::vector<Slot>&, bool);

}  // namespace dem
