#include "run_summary.h"

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <string>

namespace dem::run {
namespace {

// Six significant digits: enough to read, the CSV files keep the rest.
std::string brief(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

bool has_condition(const StopConditions& until) {
  return until.kinetic_energy_below || until.out_of_balance_below || until.servo_tolerance;
}

}  // namespace

void print_case_header(std::ostream& out, const io::CaseDefinition& definition, const World& world) {
  out << "case " << (definition.name.empty() ? "(unnamed)" : definition.name);
  if (!definition.description.empty()) out << ": " << definition.description;
  out << '\n'
      << world.particle_count() << " particles, " << world.wall_count() << " walls, " << definition.stages.size()
      << " stages\n"
      << "time step " << brief(world.time_step()) << " s (critical " << brief(world.critical_time_step())
      << " s), threads " << world.threads() << '\n';
}

void print_stage_result(std::ostream& out, int stage_index, int stage_count, const StageDef& stage,
                        const StageResult& result) {
  out << "stage " << stage_index + 1 << '/' << stage_count;
  if (!stage.name.empty()) out << ' ' << stage.name;
  out << ": " << result.cycles_run << " cycles";
  if (has_condition(stage.until)) {
    out << (result.condition_met ? ", stop condition met" : ", stop condition not met by the cycle cap");
  }
  out << '\n';
}

void print_final_state(std::ostream& out, const World& world, const std::vector<std::filesystem::path>& files) {
  const std::vector<WallMeasure> measures = world.wall_measures();
  if (!measures.empty()) {
    int name_width = 4;
    for (const WallMeasure& m : measures) {
      name_width = std::max(name_width, static_cast<int>(world.wall(m.wall).name.size()));
    }
    out << "final wall forces (N):\n"
        << "  " << std::left << std::setw(name_width) << "wall" << std::right << std::setw(14) << "fx" << std::setw(14)
        << "fy" << std::setw(14) << "normal_force" << std::setw(14) << "moment" << std::setw(10) << "contacts"
        << std::setw(14) << "eccentricity" << '\n';
    for (const WallMeasure& m : measures) {
      out << "  " << std::left << std::setw(name_width) << world.wall(m.wall).name << std::right << std::setw(14)
          << brief(m.force.x()) << std::setw(14) << brief(m.force.y()) << std::setw(14) << brief(m.normal_force)
          << std::setw(14) << brief(m.moment) << std::setw(10) << m.contacts << std::setw(14) << brief(m.eccentricity)
          << '\n';
    }
  }
  const AssemblyMeasures assembly = world.assembly_measures();
  out << "after " << world.cycle_count() << " cycles (" << brief(world.time()) << " s): kinetic energy "
      << brief(assembly.kinetic_energy) << " J, out-of-balance " << brief(assembly.out_of_balance) << ", "
      << assembly.contacts << " contacts (" << assembly.sliding_contacts << " sliding)\n"
      << "wrote";
  for (const auto& file : files) out << ' ' << file.string();
  out << '\n';
}

}  // namespace dem::run
