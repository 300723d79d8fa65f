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

}  // namespace

namespace {

// What the particles are, for the header line (a world's particles are
// all round or all shaped).
template <int Dim>
const char* particle_kind(const WorldDefT<Dim>& world) {
  const bool shaped = !world.particles.empty() && [&] {
    if constexpr (Dim == 3) {
      return world.particles.front().shape.ellipsoid();
    } else {
      return world.particles.front().shape.superquadric();
    }
  }();
  if (Dim == 3) return shaped ? "ellipsoids" : "spheres";
  if (shaped) return "superquadrics";
  return world.planar_particle == PlanarParticle::kSphere ? "spheres in a plane" : "discs";
}

// Wall resultants: the 2D table has the in-plane moment and the
// eccentricity along the wall; the 3D one the force's three components.
void print_wall_table(std::ostream& out, const World& world, int name_width) {
  out << "  " << std::left << std::setw(name_width) << "wall" << std::right << std::setw(14) << "fx" << std::setw(14)
      << "fy" << std::setw(14) << "normal_force" << std::setw(14) << "moment" << std::setw(10) << "contacts"
      << std::setw(14) << "eccentricity" << '\n';
  for (const WallMeasure& m : world.wall_measures()) {
    out << "  " << std::left << std::setw(name_width) << world.wall(m.wall).name << std::right << std::setw(14)
        << brief(m.force.x()) << std::setw(14) << brief(m.force.y()) << std::setw(14) << brief(m.normal_force)
        << std::setw(14) << brief(m.moment) << std::setw(10) << m.contacts << std::setw(14) << brief(m.eccentricity)
        << '\n';
  }
}

void print_wall_table(std::ostream& out, const World3& world, int name_width) {
  out << "  " << std::left << std::setw(name_width) << "wall" << std::right << std::setw(14) << "fx" << std::setw(14)
      << "fy" << std::setw(14) << "fz" << std::setw(14) << "normal_force" << std::setw(10) << "contacts" << '\n';
  for (const WallMeasure3& m : world.wall_measures()) {
    out << "  " << std::left << std::setw(name_width) << world.wall(m.wall).name << std::right << std::setw(14)
        << brief(m.force.x()) << std::setw(14) << brief(m.force.y()) << std::setw(14) << brief(m.force.z())
        << std::setw(14) << brief(m.normal_force) << std::setw(10) << m.contacts << '\n';
  }
}

}  // namespace

template <int Dim>
void print_case_header(std::ostream& out, const io::CaseDefinitionT<Dim>& definition, const BasicWorld<Dim>& world) {
  out << "case " << (definition.name.empty() ? "(unnamed)" : definition.name);
  if (!definition.description.empty()) out << ": " << definition.description;
  out << '\n'
      << Dim << "D: " << world.particle_count() << ' ' << particle_kind(definition.world) << ", " << world.wall_count()
      << " walls, " << definition.stages.size() << " stages\n"
      << "time step " << brief(world.time_step()) << " s (critical " << brief(world.critical_time_step())
      << " s), threads " << world.threads() << '\n';
}

template <int Dim>
void print_stage_result(std::ostream& out, int stage_index, int stage_count, const StageDefT<Dim>& stage,
                        const StageResult& result) {
  out << "stage " << stage_index + 1 << '/' << stage_count;
  if (!stage.name.empty()) out << ' ' << stage.name;
  out << ": " << result.cycles_run << " cycles";
  if (has_stop_condition(stage.until)) {
    out << (result.condition_met ? ", stop condition met" : ", stop condition not met by the cycle cap");
  }
  out << '\n';
}

template <int Dim>
void print_final_state(std::ostream& out, const BasicWorld<Dim>& world,
                       const std::vector<std::filesystem::path>& files) {
  if (world.wall_count() > 0) {
    int name_width = 4;
    for (int w = 0; w < world.wall_count(); ++w) {
      name_width = std::max(name_width, static_cast<int>(world.wall(WallId{w}).name.size()));
    }
    out << "final wall forces (N):\n";
    print_wall_table(out, world, name_width);
  }
  const AssemblyMeasures assembly = world.assembly_measures();
  out << "after " << world.cycle_count() << " cycles (" << brief(world.time()) << " s): kinetic energy "
      << brief(assembly.kinetic_energy) << " J, out-of-balance " << brief(assembly.out_of_balance) << ", "
      << assembly.contacts << " contacts (" << assembly.sliding_contacts << " sliding)\n"
      << "quasi-static: kinetic/elastic " << brief(assembly.kinetic_to_elastic) << ", unbalanced force "
      << brief(assembly.unbalanced_force) << ", inertial number " << brief(assembly.inertial_number) << '\n';
  const EnergyBudget& e = assembly.energy;
  if (world.energy_budget()) {
    out << "energy (J): gravity " << brief(e.gravity_work) << ", walls " << brief(e.wall_work) << " -> kinetic "
        << brief(e.kinetic) << ", strain " << brief(e.strain) << ", dashpots " << brief(e.contact_damping)
        << ", friction " << brief(e.friction) << ", global damping " << brief(e.global_damping) << ", local damping "
        << brief(e.local_damping) << "; residual " << brief(e.residual()) << '\n';
  }
  // The whole state in 16 hex digits: a resumed run must end at the same.
  char hash[17];
  std::snprintf(hash, sizeof(hash), "%016llx", static_cast<unsigned long long>(world.state_hash()));
  out << "state hash " << hash << '\n';
  out << "wrote";
  for (const auto& file : files) out << ' ' << file.string();
  out << '\n';
}

template void print_case_header(std::ostream&, const io::CaseDefinition&, const World&);
template void print_case_header(std::ostream&, const io::CaseDefinition3&, const World3&);
template void print_stage_result(std::ostream&, int, int, const StageDef&, const StageResult&);
template void print_stage_result(std::ostream&, int, int, const StageDef3&, const StageResult&);
template void print_final_state(std::ostream&, const World&, const std::vector<std::filesystem::path>&);
template void print_final_state(std::ostream&, const World3&, const std::vector<std::filesystem::path>&);

}  // namespace dem::run
