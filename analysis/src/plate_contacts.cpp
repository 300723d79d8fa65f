#include "dem/analysis/plate_contacts.h"

#include <algorithm>

namespace dem::analysis {

template <int Dim>
std::vector<PlateContactT<Dim>> plate_contacts(std::span<const ContactRecordT<Dim>> contacts, WallId plate) {
  std::vector<PlateContactT<Dim>> on_plate;
  for (const ContactRecordT<Dim>& c : contacts) {
    if (c.second_wall != plate) continue;
    on_plate.push_back({c.first, c.point, c.normal_force, c.shear_force, c.formed_cycle});
  }
  return on_plate;
}

template <int Dim>
std::vector<double> normal_forces(std::span<const PlateContactT<Dim>> contacts) {
  std::vector<double> forces;
  forces.reserve(contacts.size());
  for (const PlateContactT<Dim>& c : contacts) forces.push_back(c.normal_force);
  return forces;
}

template <int Dim>
PlateReading read_plate(const BasicWorld<Dim>& world, const std::vector<WallMeasureT<Dim>>& measures, WallId plate) {
  const WallMeasureT<Dim>& m = measures[plate.index()];
  return {m.normal_force, world.wall_stress(plate), world.wall_settlement(plate), m.contacts};
}

namespace {

template <int Dim>
void add_to(StateLoad& load, const PlateContactT<Dim>& c) {
  load.first_formed = load.contacts == 0 ? c.formed_cycle : std::min(load.first_formed, c.formed_cycle);
  load.last_formed = std::max(load.last_formed, c.formed_cycle);
  load.contacts += 1;
  load.load += c.normal_force;
}

}  // namespace

template <int Dim>
std::array<StateLoad, 3> load_by_state(std::span<const PlateContactT<Dim>> contacts, const StateCycles& cycles) {
  std::array<StateLoad, 3> loads;
  for (std::size_t k = 0; k < loads.size(); ++k) loads[k].state = kLoadingStates[k];
  for (const PlateContactT<Dim>& c : contacts)
    add_to(loads[static_cast<std::size_t>(state_at(c.formed_cycle, cycles))], c);
  return loads;
}

template <int Dim>
std::array<StateLoad, 3> load_by_formation_order(std::span<const PlateContactT<Dim>> contacts) {
  std::array<StateLoad, 3> loads;
  for (std::size_t k = 0; k < loads.size(); ++k) loads[k].state = kLoadingStates[k];
  std::vector<const PlateContactT<Dim>*> order;
  order.reserve(contacts.size());
  for (const PlateContactT<Dim>& c : contacts) order.push_back(&c);
  std::sort(order.begin(), order.end(), [](const auto* a, const auto* b) {
    return a->formed_cycle < b->formed_cycle || (a->formed_cycle == b->formed_cycle && a->particle < b->particle);
  });
  for (std::size_t rank = 0; rank < order.size(); ++rank) {
    // Integer comparisons 10 k < 4 n and 10 k < 7 n, so no rounding decides a group.
    const std::size_t group = 10 * rank < 4 * order.size() ? 0 : 10 * rank < 7 * order.size() ? 1 : 2;
    add_to(loads[group], *order[rank]);
  }
  return loads;
}

template std::vector<PlateContactT<2>> plate_contacts(std::span<const ContactRecordT<2>>, WallId);
template std::vector<PlateContactT<3>> plate_contacts(std::span<const ContactRecordT<3>>, WallId);
template std::vector<double> normal_forces(std::span<const PlateContactT<2>>);
template std::vector<double> normal_forces(std::span<const PlateContactT<3>>);
template PlateReading read_plate(const BasicWorld<2>&, const std::vector<WallMeasureT<2>>&, WallId);
template PlateReading read_plate(const BasicWorld<3>&, const std::vector<WallMeasureT<3>>&, WallId);
template std::array<StateLoad, 3> load_by_state(std::span<const PlateContactT<2>>, const StateCycles&);
template std::array<StateLoad, 3> load_by_state(std::span<const PlateContactT<3>>, const StateCycles&);
template std::array<StateLoad, 3> load_by_formation_order(std::span<const PlateContactT<2>>);
template std::array<StateLoad, 3> load_by_formation_order(std::span<const PlateContactT<3>>);

}  // namespace dem::analysis
