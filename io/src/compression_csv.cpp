#include "dem/io/compression_csv.h"

#include <utility>

#include "world_rows.h"

namespace dem::io {
namespace {

constexpr const char* kSamplesHeader =
    "stage,cycle,time,settlement,stress,loading_contacts,bottom_stress,bottom_contacts,contact_ratio";
constexpr const char* kContactsHeader2 =
    "snapshot,target_stress,cycle,stress,plate,particle,x,y,normal_force,shear_force,f,formed_cycle,formed_in,"
    "for_contacts,for_distribution";
constexpr const char* kContactsHeader3 =
    "snapshot,target_stress,cycle,stress,plate,particle,x,y,z,normal_force,shear_force,f,formed_cycle,formed_in,"
    "for_contacts,for_distribution";
// The snapshot's columns before those of particles.csv and contacts.csv
// (world_rows.h) in particles_at_stress.csv and contacts_at_stress.csv.
constexpr const char* kSnapshotColumns = "snapshot,target_stress,cycle,stress,";

double mean_normal_force(const auto& contacts) {
  if (contacts.empty()) return 0.0;
  double sum = 0.0;
  for (const auto& c : contacts) sum += c.normal_force;
  return sum / static_cast<double>(contacts.size());
}

}  // namespace

template <int Dim>
CompressionCsvT<Dim>::CompressionCsvT(const std::filesystem::path& directory, std::string loading_plate,
                                      std::string bottom_plate, const TableSizes* resume)
    : directory_(directory),
      loading_plate_(std::move(loading_plate)),
      bottom_plate_(std::move(bottom_plate)),
      samples_(directory, "compression.csv", kSamplesHeader, resume),
      contacts_(directory, "plate_contacts.csv", Dim == 2 ? kContactsHeader2 : kContactsHeader3, resume),
      particles_at_stress_(directory, "particles_at_stress.csv", kSnapshotColumns + particle_columns<Dim>(), resume),
      contacts_at_stress_(directory, "contacts_at_stress.csv", kSnapshotColumns + contact_columns<Dim>(), resume) {
  files_ = {samples_.path(), contacts_.path(), particles_at_stress_.path(), contacts_at_stress_.path()};
}

template <int Dim>
void CompressionCsvT<Dim>::write_sample(const dem::analysis::CompressionSample& s) {
  // Miyata Fig. 29: the loading plate's contacts over the bottom plate's.
  const double ratio = s.bottom_contacts > 0 ? static_cast<double>(s.loading_contacts) / s.bottom_contacts : 0.0;
  samples_.write_row(s.stage, s.cycle, s.time, s.settlement, s.stress, s.loading_contacts, s.bottom_stress,
                     s.bottom_contacts, ratio);
  samples_.flush();
}

template <int Dim>
void CompressionCsvT<Dim>::write_plate_rows(const dem::analysis::PlateSnapshotT<Dim>& snapshot,
                                            const std::string& plate,
                                            const std::vector<dem::analysis::PlateContactT<Dim>>& contacts,
                                            const dem::analysis::StateCycles& cycles) {
  const double mean = mean_normal_force(contacts);
  for (const dem::analysis::PlateContactT<Dim>& c : contacts) {
    const double f = mean > 0.0 ? c.normal_force / mean : 0.0;
    const std::string_view formed_in = dem::analysis::state_name(dem::analysis::state_at(c.formed_cycle, cycles));
    if constexpr (Dim == 2) {
      contacts_.write_row(snapshot.index, snapshot.target_stress, snapshot.sample.cycle, snapshot.sample.stress, plate,
                          c.particle, c.point.x(), c.point.y(), c.normal_force, c.shear_force, f, c.formed_cycle,
                          formed_in, snapshot.for_contacts, snapshot.for_distribution);
    } else {
      contacts_.write_row(snapshot.index, snapshot.target_stress, snapshot.sample.cycle, snapshot.sample.stress, plate,
                          c.particle, c.point.x(), c.point.y(), c.point.z(), c.normal_force, c.shear_force, f,
                          c.formed_cycle, formed_in, snapshot.for_contacts, snapshot.for_distribution);
    }
  }
}

template <int Dim>
void CompressionCsvT<Dim>::write_snapshot(const dem::analysis::PlateSnapshotT<Dim>& snapshot,
                                          const dem::analysis::StateCycles& cycles) {
  write_plate_rows(snapshot, loading_plate_, snapshot.loading, cycles);
  write_plate_rows(snapshot, bottom_plate_, snapshot.bottom, cycles);
  contacts_.flush();
}

template <int Dim>
void CompressionCsvT<Dim>::write_assembly(const dem::analysis::PlateSnapshotT<Dim>& snapshot,
                                          const BasicWorld<Dim>& world) {
  std::string leading;
  CsvFile::add_field(leading, snapshot.index);
  CsvFile::add_field(leading, snapshot.target_stress);
  CsvFile::add_field(leading, snapshot.sample.cycle);
  CsvFile::add_field(leading, snapshot.sample.stress);
  write_particle_rows(particles_at_stress_, world, leading);
  write_contact_rows(contacts_at_stress_, world, leading);
  particles_at_stress_.flush();
  contacts_at_stress_.flush();
}

template <int Dim>
void CompressionCsvT<Dim>::write_results(const dem::analysis::CompressionResults& r) {
  {
    CsvFile states(directory_, "compression_states.csv",
                   "state,first_cycle,samples,stress_from,stress_to,settlement_from,settlement_to,secant_stiffness,"
                   "tangent_stiffness,r_squared,loading_contacts_from,loading_contacts_to,contact_rate");
    for (const dem::analysis::StateFit& s : r.states) {
      states.write_row(dem::analysis::state_name(s.state), s.first_cycle, s.samples, s.stress_from, s.stress_to,
                       s.settlement_from, s.settlement_to, s.secant_stiffness, s.tangent_stiffness, s.r_squared,
                       s.loading_contacts_from, s.loading_contacts_to, s.contact_rate);
    }
    files_.push_back(states.path());
  }
  {
    CsvFile drops(directory_, "stress_drops.csv",
                  "state,peak_cycle,trough_cycle,peak_settlement,peak_stress,trough_stress,relative_drop");
    for (const dem::analysis::StressDrop& d : r.drops) {
      drops.write_row(dem::analysis::state_name(d.state), d.peak_cycle, d.trough_cycle, d.peak_settlement,
                      d.peak_stress, d.trough_stress, d.relative());
    }
    files_.push_back(drops.path());
  }
  // Fig. 30 two ways: by the state each contact formed in, and by the
  // order of formation (the seed's 40/30/30 % groups).
  const auto write_loads = [&](const char* name, const char* group_column,
                               const std::array<std::array<dem::analysis::StateLoad, 3>, 2>& groups) {
    CsvFile loads(directory_, name,
                  std::string("plate,") + group_column +
                      ",contacts,contact_share,load,load_share,first_formed_cycle,last_formed_cycle,stress");
    const std::string* names[] = {&loading_plate_, &bottom_plate_};
    for (std::size_t p = 0; p < 2; ++p) {
      int contacts = 0;
      double load = 0.0;
      for (const dem::analysis::StateLoad& s : groups[p]) {
        contacts += s.contacts;
        load += s.load;
      }
      for (const dem::analysis::StateLoad& s : groups[p]) {
        loads.write_row(*names[p], dem::analysis::state_name(s.state), s.contacts,
                        contacts > 0 ? static_cast<double>(s.contacts) / contacts : 0.0, s.load,
                        load > 0.0 ? s.load / load : 0.0, s.first_formed, s.last_formed, r.last.stress);
      }
    }
    files_.push_back(loads.path());
  };
  write_loads("load_by_state.csv", "state", r.load_by_state);
  write_loads("load_by_formation.csv", "group", r.load_by_formation);
  if (!r.force_distribution) return;
  CsvFile classes(directory_, "force_distribution.csv",
                  "plate,f_low,f_high,contacts,probability_density,load_share,load_density,q_model,mueth");
  CsvFile tails(directory_, "force_tail.csv",
                "plate,snapshots,contacts,mean_force,tail_from,tail_contacts,decay_rate,decay_rate_error,excess_cv,"
                "q_model_decay_rate,mueth_decay_rate");
  const std::string* names[] = {&loading_plate_, &bottom_plate_};
  for (std::size_t p = 0; p < 2; ++p) {
    const dem::analysis::PlateForceDistribution& d = (*r.force_distribution)[p];
    for (const dem::analysis::ForceClass& c : d.classes) {
      const double width = c.f_high - c.f_low, middle = 0.5 * (c.f_low + c.f_high);
      classes.write_row(*names[p], c.f_low, c.f_high, c.contacts, c.probability_density, c.load_share,
                        c.load_share / width, dem::analysis::q_model_density(middle, kQModelNeighbours),
                        dem::analysis::mueth_density(middle));
    }
    const double from = d.tail.from;
    tails.write_row(*names[p], d.snapshots, d.contacts, d.mean_force, from, d.tail.contacts, d.tail.decay_rate,
                    d.tail.decay_rate_error, d.tail.excess_cv,
                    dem::analysis::tail_decay_rate(
                        [](double f) { return dem::analysis::q_model_density(f, kQModelNeighbours); }, from),
                    dem::analysis::tail_decay_rate([](double f) { return dem::analysis::mueth_density(f); }, from));
  }
  files_.push_back(classes.path());
  files_.push_back(tails.path());
}

template <int Dim>
void record_compression(dem::analysis::CompressionAnalysisT<Dim>& analysis, CompressionCsvT<Dim>& csv,
                        const BasicWorld<Dim>& world, int stage) {
  const std::size_t before = analysis.samples().size();
  const std::vector<const dem::analysis::PlateSnapshotT<Dim>*> taken = analysis.add(world, stage);
  if (analysis.samples().size() == before) return;
  csv.write_sample(analysis.samples().back());
  const dem::analysis::CompressionSettings& s = analysis.settings();
  const dem::analysis::StateCycles cycles =
      dem::analysis::state_cycles(analysis.samples(), s.transition_stress, s.final_stress);
  for (const dem::analysis::PlateSnapshotT<Dim>* snapshot : taken) {
    csv.write_snapshot(*snapshot, cycles);
    // The world is at the snapshot's moment only now.
    if (snapshot->for_contacts) csv.write_assembly(*snapshot, world);
  }
}

template class CompressionCsvT<2>;
template class CompressionCsvT<3>;
template void record_compression(dem::analysis::CompressionAnalysisT<2>&, CompressionCsvT<2>&, const BasicWorld<2>&,
                                 int);
template void record_compression(dem::analysis::CompressionAnalysisT<3>&, CompressionCsvT<3>&, const BasicWorld<3>&,
                                 int);

}  // namespace dem::io
