// The stages a run steps: a case's loading programme as io converted it
// (none for a world restored from a snapshot), or the one stage of a cycle
// or run_until command (one_stage). Each is begun on a session's world as
// a stage of the engine's (StageRunT) that the runner steps chunk by chunk
// between the commands (docs/SERVICE.md, "Programmes").
#pragma once

#include <cstdint>
#include <string>
#include <variant>
#include <vector>

#include "dem/programme.h"
#include "dem/service/world_session.h"

namespace dem::service {

// How far a running stage is toward its end, for the status of a
// programme (docs/SERVICE.md, "Programmes"): a stage that ends on a wall's
// stress or settlement, or on a box's deviator strain, is that measure's
// share of its target (the least of them when several must hold); any
// other - a stage of fixed length, or one ending on the kinetic energy,
// the balance or the servos, which give no share - its cycles' share of its
// length or cap.
struct StageProgress {
  double fraction = 0.0;  // 0..1
  bool measured = false;  // the fraction is a measure's, not the cycles'
  std::string text;       // "top plate 405 kPa of 900 kPa", or "cycle 1200 of at most 40000"
};

class CaseProgramme {
 public:
  CaseProgramme() = default;  // no stages
  template <int Dim>
  explicit CaseProgramme(std::vector<StageDefT<Dim>> stages) : stages_(std::move(stages)) {}
  // A cycle or run_until command as a programme of one stage of the
  // world's `dimension`: `cycles`, ended early by `until` (the engine's
  // stop rule), with no start actions.
  static CaseProgramme one_stage(int dimension, std::uint64_t cycles, const StopConditions& until);

  std::size_t stage_count() const;
  const std::string& stage_name(std::size_t stage) const;
  std::uint64_t stage_cycles(std::size_t stage) const;  // its length, or its cap when it has conditions
  const StopConditions& stage_until(std::size_t stage) const;

  // Begins `stage` on `world` (a session of the programme's dimension;
  // std::bad_variant_access for the other):
  // its start actions, then its cycles. `done`: the stage's cycles run
  // already (a resumed checkpoint's): its start actions are in the state,
  // its length and minimum count from there (stage_remainder), and the
  // stepper counts only the rest. Throws what the engine throws.
  StageStepper begin_stage(std::size_t stage, WorldSession& world, std::uint64_t done = 0) const;

  // Whether a checkpoint `stage_cycles` into `stage`, with `world` as it is
  // now, can be resumed as if never interrupted: before the stage's end, on
  // one of its condition checks, and not one where the conditions hold
  // (dem/programme.h) - the stage ends there, after the row the checkpoint
  // follows.
  bool resumable_at(std::size_t stage, std::uint64_t stage_cycles, const WorldSession& world) const;
  // `stage` running on `world`, `stage_cycles` into it (stage_progress.cpp).
  StageProgress progress(std::size_t stage, std::uint64_t stage_cycles, const WorldSession& world) const;

 private:
  std::variant<std::vector<StageDefT<2>>, std::vector<StageDefT<3>>> stages_;
};

// What of `until` holds on `world`, said with the values reached: "the
// stress on top reached 1.2e+07 Pa and the kinetic energy fell to 0.9 J"
// (a run_until's reply when its conditions ended it; stage_progress.cpp).
std::string conditions_reached(const StopConditions& until, const WorldSession& world);

}  // namespace dem::service
