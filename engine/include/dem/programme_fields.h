// The field lists of the programme's structs a case sets (dem/programme.h):
// no snapshot holds them, but the case's conversion and validation walk
// them as they walk the snapshot's (io/src/case_fields.h, a rule per
// entry in io/src/case_rules.h). A new member fails the build below until
// it has its line here (and, in io, its rule).
#pragma once

#include <tuple>

#include "dem/programme.h"
#include "dem/snapshot_fields.h"

namespace dem {

template <>
struct SnapshotFields<StopConditions> {
  using Until = StopConditions;
  static constexpr auto list = std::make_tuple(
      DEM_FIELD(Until, kinetic_energy_below), DEM_FIELD(Until, out_of_balance_below),
      DEM_FIELD(Until, kinetic_to_elastic_below), DEM_FIELD(Until, unbalanced_force_below),
      DEM_FIELD(Until, servo_tolerance), DEM_FIELD(Until, deviator_strain_above), DEM_FIELD(Until, wall_stress_above),
      DEM_FIELD(Until, wall_settlement_above), DEM_FIELD(Until, region_out_of_balance_below),
      DEM_FIELD(Until, min_cycles), DEM_FIELD(Until, check_interval));
};
template <>
struct SnapshotFields<TrimDef> {
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(TrimDef, height), DEM_FIELD(TrimDef, amplitude), DEM_FIELD(TrimDef, wavelength));
};

static_assert(detail::snapshot_fields_complete<StopConditions>(),
              "StopConditions changed: give the new member its line in SnapshotFields (dem/programme_fields.h)");
static_assert(detail::snapshot_fields_complete<TrimDef>(),
              "TrimDef changed: give the new member its line in SnapshotFields (dem/programme_fields.h)");

}  // namespace dem
