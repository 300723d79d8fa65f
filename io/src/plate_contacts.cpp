#include "dem/io/plate_contacts.h"

namespace dem::io {

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
  const WallMeasureT<Dim>& m = measures[static_cast<std::size_t>(plate)];
  return {m.normal_force, m.normal_force / world.wall_area(plate), world.wall_settlement(plate), m.contacts};
}

template <int Dim>
std::array<StateLoad, 3> load_by_state(std::span<const PlateContactT<Dim>> contacts, const StateCycles& cycles) {
  std::array<StateLoad, 3> loads;
  for (std::size_t k = 0; k < loads.size(); ++k) loads[k].state = kLoadingStates[k];
  for (const PlateContactT<Dim>& c : contacts) {
    StateLoad& load = loads[static_cast<std::size_t>(state_at(c.formed_cycle, cycles))];
    load.contacts += 1;
    load.load += c.normal_force;
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

}  // namespace dem::io
