// The case targets' common path: a loaded case through validation and
// conversion to a world, the world checked, stepped a few cycles and its
// health assessed - everything dem_run and dem_server do before a run.
#pragma once

#include <variant>

#include "dem/error.h"
#include "dem/health.h"
#include "dem/io/case_conversion.h"
#include "dem/io/world_checks.h"
#include "fuzz_support.h"

namespace dem::fuzz {

template <int Dim>
void build_and_step(const io::CaseDefinitionT<Dim>& definition, const io::CaseSource& source) {
  BasicWorld<Dim> world(definition.world);
  io::check_built_world(world, definition.stages, source);
  HealthMonitorT<Dim> health(world);
  world.cycle(3);
  (void)health.assess(world);
}

// Refusals are expected; anything else aborts (a finding).
template <typename Load>
void run_case(const char* target, Load&& load) {
  try {
    io::LoadedCase loaded = load();
    loaded.source.files = files();
    loaded.source.directory = DEM_FUZZ_FILES_DIR;
    const io::AnyCaseDefinition definition = io::convert_any_case(loaded.message, loaded.source, limits());
    std::visit([&](const auto& d) { build_and_step(d, loaded.source); }, definition);
  } catch (const io::CaseError& error) {
    refused(error);
  } catch (const DefinitionError& error) {
    refused(error);
  } catch (const std::exception& error) {
    unexpected(target, error);
  }
}

}  // namespace dem::fuzz
