#include "contact_table.h"

#include <cassert>

namespace dem {

namespace {

template <int Dim>
std::int32_t first_of(const PairContact<Dim>& c) { return c.first; }
template <int Dim>
std::int32_t second_of(const PairContact<Dim>& c) { return c.second; }
template <int Dim>
std::int32_t first_of(const WallContact<Dim>& c) { return c.particle; }
template <int Dim>
std::int32_t second_of(const WallContact<Dim>& c) { return c.wall; }

template <typename Contact>
inline constexpr bool kIsPair = false;
template <int Dim>
inline constexpr bool kIsPair<PairContact<Dim>> = true;

// Merges the sorted new keys with the sorted old entries, keeping the history
// of every key present in both: linear in the table size and deterministic.
template <typename Contact>
std::vector<Contact> merge(const std::vector<Contact>& old_entries, const std::vector<Candidate>& keys) {
  std::vector<Contact> merged;
  merged.reserve(keys.size());
  std::size_t o = 0;
  auto before = [](const Contact& c, const Candidate& k) {
    return first_of(c) < k.first || (first_of(c) == k.first && second_of(c) < k.second);
  };
  for (const Candidate& key : keys) {
    while (o < old_entries.size() && before(old_entries[o], key)) ++o;
    const bool kept = o < old_entries.size() && first_of(old_entries[o]) == key.first &&
                      second_of(old_entries[o]) == key.second;
    if (kept) {
      merged.push_back(old_entries[o]);
    } else {
      Contact fresh{};
      if constexpr (kIsPair<Contact>) {
        fresh.first = key.first;
        fresh.second = key.second;
      } else {
        fresh.particle = key.first;
        fresh.wall = key.second;
      }
      merged.push_back(fresh);
    }
  }
  return merged;
}

// CSR index from each contact's owners, in contact order, so that each
// particle's entries come in a fixed order whatever the thread count.
void build_index(const std::vector<std::int32_t>& first_owner, const std::vector<std::int32_t>* second_owner,
                 int particle_count, std::vector<std::int32_t>& offsets, std::vector<std::int32_t>& entries) {
  offsets.assign(particle_count + 1, 0);
  for (std::int32_t p : first_owner) ++offsets[p + 1];
  if (second_owner) {
    for (std::int32_t p : *second_owner) ++offsets[p + 1];
  }
  for (int p = 0; p < particle_count; ++p) offsets[p + 1] += offsets[p];
  entries.resize(offsets[particle_count]);
  std::vector<std::int32_t> cursor(offsets.begin(), offsets.end() - 1);
  for (std::size_t c = 0; c < first_owner.size(); ++c) {
    const auto id = static_cast<std::int32_t>(c);
    if (second_owner) {
      entries[cursor[first_owner[c]]++] = 2 * id;
      entries[cursor[(*second_owner)[c]]++] = 2 * id + 1;
    } else {
      entries[cursor[first_owner[c]]++] = id;
    }
  }
}

}  // namespace

template <int Dim>
void rebuild_contacts(ContactTable<Dim>& table, const std::vector<Candidate>& pair_candidates,
                      const std::vector<Candidate>& wall_candidates, int particle_count) {
  table.pairs = merge(table.pairs, pair_candidates);
  table.walls = merge(table.walls, wall_candidates);
  // Outputs of the next force pass; every entry is rewritten there.
  table.pair_forces.assign(table.pairs.size(), ContactForce<Dim>{});
  table.wall_forces.assign(table.walls.size(), ContactForce<Dim>{});
  reindex_contacts(table, particle_count);
}

template <int Dim>
void reindex_contacts(ContactTable<Dim>& table, int particle_count) {
  std::vector<std::int32_t> firsts(table.pairs.size()), seconds(table.pairs.size());
  for (std::size_t c = 0; c < table.pairs.size(); ++c) {
    assert(table.pairs[c].first < table.pairs[c].second);
    firsts[c] = table.pairs[c].first;
    seconds[c] = table.pairs[c].second;
  }
  build_index(firsts, &seconds, particle_count, table.index.pair_offsets, table.index.pair_entries);
  std::vector<std::int32_t> owners(table.walls.size());
  for (std::size_t c = 0; c < table.walls.size(); ++c) owners[c] = table.walls[c].particle;
  build_index(owners, nullptr, particle_count, table.index.wall_offsets, table.index.wall_entries);
}

template void reindex_contacts(ContactTable<2>&, int);
template void reindex_contacts(ContactTable<3>&, int);
template void rebuild_contacts(ContactTable<2>&, const std::vector<Candidate>&, const std::vector<Candidate>&, int);
template void rebuild_contacts(ContactTable<3>&, const std::vector<Candidate>&, const std::vector<Candidate>&, int);

}  // namespace dem
