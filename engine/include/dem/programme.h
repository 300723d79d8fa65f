// A loading programme: stages that set wall motions and cycle the world for a
// number of cycles or until a condition holds. Used by dem_run and the service.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "dem/definitions.h"
#include "dem/world.h"

namespace dem {

// A threshold on one wall.
struct WallThreshold {
  WallId wall = kInvalidId;
  double value = 0.0;
};

// Conditions that end a stage early - the one stop rule of the project
// (dem_run's stages, the service's run_programme and run_until): the stage
// ends when EVERY condition that is set holds at once (a conjunction). The
// direction of each is fixed by its name: kinetic energy, out of balance
// and the quasi-static measures from above ("below"), wall stress, settlement and deviator strain from
// below ("above"); a target already passed at the first check ends the stage
// there. They are checked every check_interval cycles, never before
// min_cycles.
struct StopConditions {
  std::optional<double> kinetic_energy_below;  // J
  std::optional<double> out_of_balance_below;  // Delta F / F
  // Quasi-static measures (AssemblyMeasures): kinetic over elastic energy,
  // and the mean unbalanced force over the mean contact force; both hold
  // only with contacts.
  std::optional<double> kinetic_to_elastic_below;
  std::optional<double> unbalanced_force_below;
  // Every servo-controlled wall carries its target within this relative
  // error, and so does every stress-controlled axis of the box control.
  std::optional<double> servo_tolerance;
  // The box control's deviator strain (its largest axis strain minus its
  // smallest, BoxMeasureT) has reached this.
  std::optional<double> deviator_strain_above;
  std::optional<WallThreshold> wall_stress_above;      // Pa: normal force over wall_area
  std::optional<WallThreshold> wall_settlement_above;  // m: wall_settlement
  std::uint64_t min_cycles = 0;
  std::uint64_t check_interval = 10;
};

// Whether any condition is set (a stage without any runs its cycles).
bool has_stop_condition(const StopConditions& until);

// Whether the conditions that are set all hold now - the rule run_stage
// applies at its checks. A checkpoint taken at a check must know it: the
// stage ends there, so a run resumed from it would run past the end.
template <int Dim>
bool stop_conditions_hold(const BasicWorld<Dim>& world, const StopConditions& until);

// Trimming a sample's surface (Miyata et al. 2002, 3.1): particles whose
// centres lie above height + amplitude sin(2 pi x / wavelength) are
// removed, "above" along the last axis (y in 2D, z in 3D), x along the
// first. Amplitude 0 is a smooth surface; eq. 60 the rough one.
struct TrimDef {
  double height = 0.0;      // m
  double amplitude = 0.0;   // m
  double wavelength = 1.0;  // m, > 0
};

// Placing a wall on a sample: the wall moves along its normal until it
// stands `clearance` beyond the furthest particle on its side (a loading
// plate set on the sample's top, Miyata et al. 2002, 3.1).
struct PlaceWallDef {
  WallId wall = kInvalidId;
  double clearance = 0.0;  // m
};

// A time step: fixed seconds, or a fraction of the critical step.
struct TimeStepSetting {
  double fraction = 0.0;  // (0, 1] when fixed is 0
  double fixed = 0.0;     // s, > 0 overrides the fraction
};

template <int Dim>
struct StageDefT {
  std::string name;
  // Done when the stage starts, in this order: trim, place a wall, remove
  // walls, then the wall motions, the box control, damping, time step and
  // friction.
  std::optional<TrimDef> trim;
  std::optional<PlaceWallDef> place_wall;
  std::vector<WallId> remove_walls;                               // taken out when the stage starts
  std::vector<std::pair<WallId, WallMotionT<Dim>>> wall_motions;  // applied when the stage starts
  // The box control from this stage on: set (or replaced) by box_control,
  // released by release_box_control; otherwise it stays as it was.
  std::optional<BoxControlT<Dim>> box_control;
  bool release_box_control = false;
  std::optional<DampingDef> damping;                     // applied when the stage starts
  std::optional<TimeStepSetting> time_step;              // from this stage on
  std::vector<std::pair<MaterialId, double>> frictions;  // materials' friction from this stage on
  std::uint64_t cycles = 0;                              // the stage's length, or its cap when conditions are set
  StopConditions until;
};

struct StageResult {
  std::uint64_t cycles_run = 0;
  bool condition_met = false;  // a stop condition ended the stage before its cycle cap
};

// Called every `interval` cycles counted from the stage's start, so a caller
// can record outputs; return false to stop the stage.
template <int Dim>
using StageObserverT = std::function<bool(const BasicWorld<Dim>&)>;

// One stage stepped a piece at a time: run_stage's loop turned inside out,
// for a caller that does other work between the pieces (the service
// answers commands between chunks of cycles, in its own loop rather than
// inside the stage's). Made, it has done the stage's start actions; then
// cycle() and check() in turn, as run_stage does, until over(). The
// conditions are checked (the stop rule above) every check_interval
// cycles from the stage's start, from min_cycles on.
template <int Dim>
class StageRunT {
 public:
  StageRunT(BasicWorld<Dim>& world, StageDefT<Dim> stage);

  // Cycles to the stage's next condition check or its end; 0 once over.
  std::uint64_t cycles_to_next_stop() const;
  // Runs `cycles`, at most cycles_to_next_stop().
  void cycle(std::uint64_t cycles);
  // At a condition check, whether the conditions hold; at the stage's
  // length, its end. True when the stage is over.
  bool check();
  bool over() const { return over_; }
  const StageResult& result() const { return result_; }
  const StageDefT<Dim>& stage() const { return stage_; }

 private:
  BasicWorld<Dim>* world_;
  StageDefT<Dim> stage_;
  bool conditional_;
  std::uint64_t check_interval_;
  StageResult result_;
  bool over_ = false;
};

// The observer is not used to deduce Dim, so a lambda can be passed as it is.
template <int Dim>
StageResult run_stage(BasicWorld<Dim>& world, const StageDefT<Dim>& stage, std::uint64_t interval = 0,
                      const std::type_identity_t<StageObserverT<Dim>>& observer = {});

// The rest of a stage resumed `done` cycles into it (a checkpoint's): its
// start actions - all of them, including the box control, whose strain
// reference would otherwise move to the resumed state - are done and in
// the state, so they go; the cycles and min_cycles left count from there.
template <int Dim>
StageDefT<Dim> stage_remainder(StageDefT<Dim> stage, std::uint64_t done);

using StageDef = StageDefT<2>;
using StageDef3 = StageDefT<3>;
using StageObserver = StageObserverT<2>;
using StageRun = StageRunT<2>;
using StageRun3 = StageRunT<3>;

}  // namespace dem
