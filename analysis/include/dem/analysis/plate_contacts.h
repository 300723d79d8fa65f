// What a plate carries (Miyata et al. 2002, 3.2-3.3): its stress and
// settlement, the contacts on it with their positions and normal forces
// (Fig. 34), and the share of its load carried by the contacts formed in
// each state of the loading (Fig. 30). Functions over the engine's public
// measures and contact records, in 2D and 3D.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "dem/analysis/loading_states.h"
#include "dem/measures.h"
#include "dem/world.h"

namespace dem::analysis {

template <int Dim>
struct PlateContactT {
  ParticleId particle = kInvalidId;
  Vec<Dim> point = Vec<Dim>::Zero();  // m
  double normal_force = 0.0;          // N: the load the contact puts on the plate (spring part, as contacts.csv)
  double shear_force = 0.0;           // N: signed in 2D, the magnitude in 3D
  std::uint64_t formed_cycle = 0;     // the cycle it began touching
};

// The touching contacts on one wall, in the engine's order.
template <int Dim>
std::vector<PlateContactT<Dim>> plate_contacts(std::span<const ContactRecordT<Dim>> contacts, WallId plate);

template <int Dim>
std::vector<double> normal_forces(std::span<const PlateContactT<Dim>> contacts);

// A plate's normal force, its stress (over World::wall_area) and its
// settlement (World::wall_settlement).
struct PlateReading {
  double normal_force = 0.0;  // N
  double stress = 0.0;        // Pa
  double settlement = 0.0;    // m
  int contacts = 0;
};

template <int Dim>
PlateReading read_plate(const BasicWorld<Dim>& world, const std::vector<WallMeasureT<Dim>>& measures, WallId plate);

// A group of the contacts on a plate, and the normal force they carry.
struct StateLoad {
  LoadingState state = LoadingState::kInitial;
  int contacts = 0;
  double load = 0.0;               // N
  std::uint64_t first_formed = 0;  // the earliest and latest cycle its contacts formed in (0 when empty)
  std::uint64_t last_formed = 0;
};

// The contacts grouped by the state of the stress-settlement curve
// (Miyata 3.2(3)) they formed in.
template <int Dim>
std::array<StateLoad, 3> load_by_state(std::span<const PlateContactT<Dim>> contacts, const StateCycles& cycles);

// Miyata Fig. 30 as the seed defines it: the plate's contacts in the order
// they formed (ties by particle id); "the first 40 % of the contact points
// newly created" are the initial group, "those formed between 40 and 70 %"
// the transition group and the last 30 % the final group, so equal loads
// would give 40/30/30 %. A contact of rank k (from 0) of n is initial when
// k < 0.4 n, transition when k < 0.7 n, final otherwise.
template <int Dim>
std::array<StateLoad, 3> load_by_formation_order(std::span<const PlateContactT<Dim>> contacts);

}  // namespace dem::analysis
