// A case in the engine's terms: what case_conversion produces and dem_run
// (and the service) consume.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "dem/analysis/compression_settings.h"
#include "dem/analysis/region.h"
#include "dem/definitions.h"
#include "dem/ids.h"
#include "dem/programme.h"

namespace dem::io {

// A contact between two particles followed through the run (probes.csv).
struct Probe {
  std::string name;
  ParticleId first = kInvalidId;
  ParticleId second = kInvalidId;
};

// A region measured at every output row (regions.csv): written once for
// both dimensions, as the case gives it; region_for turns it into the
// analysis layer's region.
struct MeasurementRegion {
  std::string name;
  analysis::RegionShape shape = analysis::RegionShape::kWhole;
  Vec3 min = Vec3::Zero(), max = Vec3::Zero();  // m, box
  Vec3 centre = Vec3::Zero();                   // m, ball
  double radius = 0.0;                          // m, ball
};

template <int Dim>
analysis::RegionT<Dim> region_for(const MeasurementRegion& r) {
  analysis::RegionT<Dim> region;
  region.name = r.name;
  region.shape = r.shape;
  region.min = r.min.head<Dim>();
  region.max = r.max.head<Dim>();
  region.centre = r.centre.head<Dim>();
  region.radius = r.radius;
  return region;
}

struct OutputSettings {
  std::uint64_t interval = 100;  // cycles between rows of the time series
  bool contacts_file = true;     // write contacts.csv at the end
  std::vector<Probe> probes;
  std::optional<analysis::CompressionSettings> compression;  // the plate loading analyses, when asked for
  std::uint64_t vtk_interval = 0;                            // cycles between ParaView files; 0 = none
  std::vector<MeasurementRegion> regions;                    // measured at every row (regions.csv)
};

// Written once over the dimension, like the engine's definitions: the 2D
// name is the Dim = 2 instance, the 3D one ends in 3.
template <int Dim>
struct CaseDefinitionT {
  std::string name;
  std::string description;
  WorldDefT<Dim> world;
  std::vector<StageDefT<Dim>> stages;
  OutputSettings output;
};

using CaseDefinition = CaseDefinitionT<2>;
using CaseDefinition3 = CaseDefinitionT<3>;

// A case in whichever dimension it declares; a program that runs both
// visits it once and goes on in templates.
using AnyCaseDefinition = std::variant<CaseDefinition, CaseDefinition3>;

}  // namespace dem::io
