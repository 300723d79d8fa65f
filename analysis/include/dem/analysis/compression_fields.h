// The field lists of the plate loading analyses' settings
// (compression_settings.h): no snapshot holds them, but the case's
// conversion and validation walk them as they walk the snapshot's
// (io/src/case_fields.h, a rule per entry in io/src/case_rules.h). A new
// member fails the build below until it has its line here (and, in io,
// its rule).
#pragma once

#include <tuple>

#include "dem/analysis/compression_settings.h"
#include "dem/snapshot_fields.h"

namespace dem {

template <>
struct SnapshotFields<analysis::ForceDistributionSettings> {
  using Settings = analysis::ForceDistributionSettings;
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(Settings, stress_from), DEM_FIELD(Settings, stress_to), DEM_FIELD(Settings, snapshots),
                      DEM_FIELD(Settings, bin_width), DEM_FIELD(Settings, tail_from));
};
template <>
struct SnapshotFields<analysis::CompressionSettings> {
  using Settings = analysis::CompressionSettings;
  static constexpr auto list =
      std::make_tuple(DEM_FIELD(Settings, loading_plate), DEM_FIELD(Settings, bottom_plate),
                      DEM_FIELD(Settings, loading_stage), DEM_FIELD(Settings, transition_stress),
                      DEM_FIELD(Settings, final_stress), DEM_FIELD(Settings, contacts_at_stress),
                      DEM_FIELD(Settings, force_distribution), DEM_FIELD(Settings, stress_drop_fraction));
};

static_assert(detail::snapshot_fields_complete<analysis::ForceDistributionSettings>(),
              "ForceDistributionSettings changed: give the new member its line (dem/analysis/compression_fields.h)");
static_assert(detail::snapshot_fields_complete<analysis::CompressionSettings>(),
              "CompressionSettings changed: give the new member its line (dem/analysis/compression_fields.h)");

}  // namespace dem
