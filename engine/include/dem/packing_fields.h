// The field lists of the particle generators' definitions (dem/packing.h):
// no snapshot holds them, but the case's conversion and validation walk
// them as they walk the snapshot's (io/src/case_fields.h, a rule per
// entry in io/src/case_rules.h). A new member fails the build below until
// it has its line here (and, in io, its rule).
#pragma once

#include <tuple>

#include "dem/packing.h"
#include "dem/snapshot_fields.h"

namespace dem {

template <int Dim>
struct SnapshotFields<LatticeDefT<Dim>> {
  using Lattice = LatticeDefT<Dim>;
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(Lattice, material), DEM_FIELD(Lattice, radius), DEM_FIELD(Lattice, origin),
                      DEM_FIELD(Lattice, columns), DEM_FIELD(Lattice, rows), DEM_FIELD(Lattice, layers),
                      DEM_FIELD(Lattice, spacing), DEM_FIELD(Lattice, arrangement));
};
template <int Dim>
struct SnapshotFields<RandomPackingDefT<Dim>> {
  using Packing = RandomPackingDefT<Dim>;
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(Packing, material), DEM_FIELD(Packing, min), DEM_FIELD(Packing, max),
                      DEM_FIELD(Packing, sizes), DEM_FIELD(Packing, seed), DEM_FIELD(Packing, max_attempts),
                      DEM_FIELD(Packing, next_size_when_full), DEM_FIELD(Packing, stopped));
};

#define DEM_PACKING_FIELDS_COMPLETE(...)                         \
  static_assert(detail::snapshot_fields_complete<__VA_ARGS__>(), \
                #__VA_ARGS__ " changed: give the new member its line in SnapshotFields (dem/packing_fields.h)")
DEM_PACKING_FIELDS_COMPLETE(LatticeDefT<2>);
DEM_PACKING_FIELDS_COMPLETE(LatticeDefT<3>);
DEM_PACKING_FIELDS_COMPLETE(RandomPackingDefT<2>);
DEM_PACKING_FIELDS_COMPLETE(RandomPackingDefT<3>);
#undef DEM_PACKING_FIELDS_COMPLETE

}  // namespace dem
