#include "verification.h"

#include <chrono>
#include <cmath>
#include <cstdio>

#include "dem/io/case_conversion.h"
#include "dem/io/case_loader.h"
#include "dem/io/csv_file.h"
#include "dem/programme.h"

namespace dem::validation {

namespace {

// The walls' F_H / F_V and the rest of Table 1's columns, now.
VerificationStage read_stage(const World& world, const std::string& name, bool settled) {
  VerificationStage s;
  s.name = name;
  s.settled = settled;
  s.cycle = world.cycle_count();
  const auto walls = world.wall_measures();
  for (std::size_t k = 0; k < 4; ++k) {
    s.walls[k] = walls[k];
    const WallDef& wall = world.wall(WallId::from_index(k));
    const double shear = walls[k].force.dot(wall.direction);
    if (walls[k].normal_force > 0.0) {
      s.largest_wall_obliquity = std::max(s.largest_wall_obliquity, std::abs(shear) / walls[k].normal_force);
    }
  }
  const double vertical = 0.5 * (walls[0].normal_force + walls[2].normal_force);
  const double horizontal = 0.5 * (walls[1].normal_force + walls[3].normal_force);
  s.ratio = horizontal / vertical;
  const AssemblyMeasures a = world.assembly_measures();
  s.out_of_balance = a.out_of_balance;
  s.contacts = a.contacts;
  s.sliding = a.sliding_contacts;
  return s;
}

}  // namespace

VerificationRun run_verification(const std::filesystem::path& case_file) {
  const auto start = std::chrono::steady_clock::now();
  const io::LoadedCase loaded = io::load_case_file(case_file);
  const io::CaseDefinition def = io::convert_case(loaded.message, loaded.source);
  VerificationRun run;
  run.name = def.name;
  run.wall_friction = def.world.materials[def.world.walls.front().material.index()].friction;
  World world(def.world);
  bool settled = true;
  for (const StageDef& stage : def.stages) {
    const StageResult result = run_stage(world, stage);
    settled = settled && result.condition_met;
    if (stage.name == "settle") {
      run.a = read_stage(world, "A", settled);
      settled = true;
    }
  }
  run.b = read_stage(world, "B", settled);
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

void print_verification(std::FILE* out, const VerificationRun& run) {
  std::fprintf(out, "%s (%.1f s): tan(phi) disc to wall %.2f\n", run.name.c_str(), run.seconds, run.wall_friction);
  for (const VerificationStage* s : {&run.a, &run.b}) {
    std::fprintf(out, "  stage %s after %llu cycles%s: F_H/F_V = %.4f, Delta F / F = %.3f%%, %d contacts, %d sliding\n",
                 s->name.c_str(), static_cast<unsigned long long>(s->cycle), s->settled ? "" : " (NOT settled)",
                 s->ratio, 100.0 * s->out_of_balance, s->contacts, s->sliding);
    std::fprintf(out, "    wall  F_1          F_2          e/(L/2)   contacts\n");
    for (const WallMeasure& m : s->walls) {
      std::fprintf(out, "    %d     %+.4e  %+.4e  %6.2f%%   %d\n", m.wall.value() + 1, m.force.x(), m.force.y(),
                   100.0 * m.eccentricity, m.contacts);
    }
    std::fprintf(out, "    largest |wall shear| / wall normal force %.4f (tan phi disc to wall %.2f)\n",
                 s->largest_wall_obliquity, run.wall_friction);
  }
}

void write_verification_csv(const std::filesystem::path& out, const VerificationRun& run) {
  io::CsvFile csv(out, "verification.csv",
                  "case,stage,cycle,settled,ratio,out_of_balance,contacts,sliding,wall,f_1,f_2,normal_force,"
                  "eccentricity,wall_contacts");
  for (const VerificationStage* s : {&run.a, &run.b}) {
    for (const WallMeasure& m : s->walls) {
      csv.write_row(run.name, s->name, s->cycle, s->settled, s->ratio, s->out_of_balance, s->contacts, s->sliding,
                    m.wall.value() + 1, m.force.x(), m.force.y(), m.normal_force, m.eccentricity, m.contacts);
    }
  }
}

Verdict judge_verification(const VerificationRun& run) {
  Verdict v;
  // Stage A -> B: F_V up 4.348 %, F_H down 4.348 %.
  constexpr double kStepUp = 1.04348, kStepDown = 0.95652;
  for (const VerificationStage* s : {&run.a, &run.b}) {
    const std::string stage = "stage " + s->name;
    v.expect(stage + ": settled within its cycles", s->settled);
    v.near(stage + ": F_H / F_V", s->ratio, s->name == "A" ? 0.4 : 0.4 * kStepDown / kStepUp, 0.01);
    v.below(stage + ": Delta F / F (seed: 0.1 to 4.2 %)", s->out_of_balance, 0.01);
    // Eq. 19 at every wall contact bounds the wall's resultant (the normal
    // dashpots of the contacts, c = beta k n_dot, add at most a few 1e-4 to
    // the normal force of walls near rest).
    v.at_least(stage + ": tan(phi) disc to wall x 1.001 against the largest |wall shear| / normal force",
               1.001 * run.wall_friction, s->largest_wall_obliquity);
    for (const WallMeasure& m : s->walls) {
      v.above(stage + ": contacts on wall " + std::to_string(m.wall.value() + 1), m.contacts, 2);
    }
  }
  return v;
}

}  // namespace dem::validation
