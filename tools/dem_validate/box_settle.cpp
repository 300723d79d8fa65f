#include "box_settle.h"

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/programme.h"
#include "dem/world.h"

namespace dem::validation {

BoxSettleResult box_settle(const std::filesystem::path& case_file) {
  const io::LoadedCase loaded = io::load_case_file(case_file);
  const io::CaseDefinition3 def = io::convert_case<3>(loaded.message, loaded.source);
  World3 world(def.world);
  BoxSettleResult r;
  r.particles = world.particle_count();
  const Vec3 gravity = world.gravity();
  for (double m : world.particles().mass) r.weight += m * gravity.norm();
  r.at_rest = true;
  for (const StageDef3& stage : def.stages) r.at_rest = run_stage(world, stage).condition_met && r.at_rest;
  r.cycles = world.cycle_count();
  const auto walls = world.wall_measures();
  r.floor_force = -walls[0].force.z();
  for (std::size_t w = 1; w < walls.size(); ++w) r.side_walls_vertical -= walls[w].force.z();
  r.energy = world.assembly_measures().energy;
  return r;
}

}  // namespace dem::validation
