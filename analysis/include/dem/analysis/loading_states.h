// The three states of a plate loading test (Miyata et al. 2002, 3.2(3)):
// a large settlement at low stress (initial), a stiffening (transition),
// and a nearly linear stress-settlement relation (final), bounded by two
// stresses of the loading plate (the seed's 50 and 250 kPa). A moment of
// the run belongs to the state the stress had first reached by then, so
// the stress falling back after a drop does not return the sample to an
// earlier state.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace dem::analysis {

enum class LoadingState { kInitial, kTransition, kFinal };
inline constexpr std::array<LoadingState, 3> kLoadingStates = {LoadingState::kInitial, LoadingState::kTransition,
                                                               LoadingState::kFinal};
std::string_view state_name(LoadingState state);  // "initial", "transition", "final"

// One row of the loading: the loading plate's settlement and normal stress
// and the contacts on both plates.
struct CompressionSample {
  int stage = 0;  // index into the case's stages
  std::uint64_t cycle = 0;
  double time = 0.0;        // s
  double settlement = 0.0;  // m, of the loading plate since it was placed
  double stress = 0.0;      // Pa, the loading plate's normal force over its area
  int loading_contacts = 0;
  double bottom_stress = 0.0;  // Pa
  int bottom_contacts = 0;
};

// The first cycles at which the loading plate's stress reached the
// transition and final bounds; unset while it has not.
struct StateCycles {
  std::optional<std::uint64_t> transition;
  std::optional<std::uint64_t> final;
};

StateCycles state_cycles(std::span<const CompressionSample> samples, double transition_stress, double final_stress);

// The state a cycle belongs to: a contact formed at that cycle, or a sample.
LoadingState state_at(std::uint64_t cycle, const StateCycles& cycles);

// A state's part of the stress-settlement curve, from the loading plate's
// first contact on (before it the plate only approaches the sample).
struct StateFit {
  LoadingState state = LoadingState::kInitial;
  int samples = 0;
  std::uint64_t first_cycle = 0;  // of the state's first sample
  double stress_from = 0.0;       // Pa, at the state's first sample
  double stress_to = 0.0;         // Pa, at its last
  double settlement_from = 0.0;   // m
  double settlement_to = 0.0;     // m
  // The stress gained over the settlement from the first sample to the
  // last, Pa/m: robust where few contacts make the stress jump.
  double secant_stiffness = 0.0;
  // Least-squares line of stress against settlement: its slope, the
  // tangent stiffness (Pa/m), and R^2 (1 for a straight line).
  double tangent_stiffness = 0.0;
  double r_squared = 0.0;
  int loading_contacts_from = 0;
  int loading_contacts_to = 0;
  // Least-squares slope of the loading plate's contact count against its
  // stress, contacts per Pa (Figs. 29 and 33: fast, then slower).
  double contact_rate = 0.0;
};

std::array<StateFit, 3> fit_states(std::span<const CompressionSample> samples, const StateCycles& cycles);

}  // namespace dem::analysis
