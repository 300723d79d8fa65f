// A case in the engine's terms: what case_conversion produces and dem_run
// (and the service) consume.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

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

struct OutputSettings {
  std::uint64_t interval = 100;  // cycles between rows of the time series
  bool contacts_file = true;     // write contacts.csv at the end
  std::vector<Probe> probes;
};

struct CaseDefinition {
  std::string name;
  std::string description;
  WorldDef world;
  std::vector<StageDef> stages;
  OutputSettings output;
};

}  // namespace dem::io
