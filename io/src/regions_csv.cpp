#include "dem/io/regions_csv.h"

#include <string>
#include <utility>

namespace dem::io {

namespace {

constexpr const char* kAxes[] = {"x", "y", "z"};

// Tensor components, all of them (the stress need not be symmetric) or the
// upper triangle (fabrics are).
std::string tensor_columns(const std::string& name, int dim, bool symmetric) {
  std::string columns;
  for (int i = 0; i < dim; ++i) {
    for (int j = symmetric ? i : 0; j < dim; ++j) columns += "," + name + "_" + kAxes[i] + kAxes[j];
  }
  return columns;
}

std::string principal_columns(const std::string& name, int dim) {
  std::string columns;
  for (int k = 1; k <= dim; ++k) columns += "," + name + "_" + std::to_string(k);
  if (dim == 2) return columns + "," + name + "_angle";
  for (int i = 0; i < dim; ++i) columns += "," + name + "_major_" + kAxes[i];
  return columns;
}

template <int Dim>
void add_tensor(std::vector<double>& v, const analysis::Tensor<Dim>& t, bool symmetric) {
  for (int i = 0; i < Dim; ++i) {
    for (int j = symmetric ? i : 0; j < Dim; ++j) v.push_back(t(i, j));
  }
}

template <int Dim>
void add_principal(std::vector<double>& v, const analysis::Principal<Dim>& p) {
  for (int k = 0; k < Dim; ++k) v.push_back(p.values[k]);
  if constexpr (Dim == 2) {
    v.push_back(p.angle);
  } else {
    for (int i = 0; i < Dim; ++i) v.push_back(p.directions(i, 0));
  }
}

template <int Dim>
std::string box_header() {
  std::string header = "cycle,time";
  for (const char* name : {"extent", "stress", "target", "strain"}) {
    for (int i = 0; i < Dim; ++i) header += std::string(",") + name + "_" + kAxes[i];
  }
  return header + ",volumetric_strain,deviator_strain,mean_stress";
}

}  // namespace

template <int Dim>
std::string region_columns() {
  std::string columns =
      "particles,rattlers,contacts,particle_contacts,sliding_contacts,sliding_fraction,coordination,"
      "mechanical_coordination,porosity,void_ratio";
  columns += tensor_columns("stress", Dim, false);
  columns += principal_columns("stress", Dim);
  columns += ",mean_stress,deviator_stress,sin_phi,tangential_share";
  columns += tensor_columns("fabric", Dim, true) + principal_columns("fabric", Dim) + ",anisotropy";
  columns +=
      tensor_columns("weighted_fabric", Dim, true) + principal_columns("weighted_fabric", Dim) + ",weighted_anisotropy";
  columns += ",fabric_trace,mean_normal_force,max_normal_force,mean_rotation,mean_abs_rotation";
  return columns;
}

template <int Dim>
std::vector<double> region_values(const analysis::RegionMeasuresT<Dim>& m) {
  std::vector<double> v = {static_cast<double>(m.particles),
                           static_cast<double>(m.rattlers),
                           static_cast<double>(m.contacts),
                           static_cast<double>(m.particle_contacts),
                           static_cast<double>(m.sliding_contacts),
                           m.sliding_fraction,
                           m.coordination,
                           m.mechanical_coordination,
                           m.porosity,
                           m.void_ratio};
  add_tensor<Dim>(v, m.stress, false);
  add_principal<Dim>(v, m.principal_stress);
  v.insert(v.end(), {m.mean_stress, m.deviator_stress, m.sin_phi, m.tangential_share});
  add_tensor<Dim>(v, m.fabric.tensor, true);
  add_principal<Dim>(v, m.fabric.principal);
  v.push_back(m.fabric.anisotropy);
  add_tensor<Dim>(v, m.weighted_fabric.tensor, true);
  add_principal<Dim>(v, m.weighted_fabric.principal);
  v.push_back(m.weighted_fabric.anisotropy);
  v.insert(v.end(), {m.fabric_trace, m.mean_normal_force, m.max_normal_force, m.mean_rotation, m.mean_abs_rotation});
  return v;
}

template <int Dim>
RegionsCsvT<Dim>::RegionsCsvT(const std::filesystem::path& directory, std::vector<analysis::RegionT<Dim>> regions,
                              const TableSizes* resume)
    : file_(directory, "regions.csv", "cycle,time,region," + region_columns<Dim>(), resume),
      regions_(std::move(regions)) {
  for (const auto& region : regions_) analysis::check_region(region);
}

template <int Dim>
std::vector<analysis::RegionMeasuresT<Dim>> RegionsCsvT<Dim>::write(const BasicWorld<Dim>& world) {
  const analysis::AssemblySampleT<Dim> sample = analysis::sample(world);
  std::vector<analysis::RegionMeasuresT<Dim>> measures;
  measures.reserve(regions_.size());
  for (const auto& region : regions_) {
    measures.push_back(analysis::measure_region(sample, region));
    file_.write_row_then(region_values<Dim>(measures.back()), world.cycle_count(), world.time(), region.name);
  }
  file_.flush();
  return measures;
}

template <int Dim>
BoxCsvT<Dim>::BoxCsvT(const std::filesystem::path& directory, const TableSizes* resume)
    : file_(directory, "box.csv", box_header<Dim>(), resume) {}

template <int Dim>
void BoxCsvT<Dim>::write(const BasicWorld<Dim>& world) {
  if (!world.box_control()) return;
  const BoxMeasureT<Dim> m = world.box_measure();
  std::vector<double> v;
  for (const Vec<Dim>* x : {&m.extent, &m.stress, &m.target, &m.strain}) {
    for (int i = 0; i < Dim; ++i) v.push_back((*x)[i]);
  }
  v.insert(v.end(), {m.volumetric_strain, m.deviator_strain, m.mean_stress});
  file_.write_row_then(v, world.cycle_count(), world.time());
  file_.flush();
}

template std::string region_columns<2>();
template std::string region_columns<3>();
template std::vector<double> region_values(const analysis::RegionMeasuresT<2>&);
template std::vector<double> region_values(const analysis::RegionMeasuresT<3>&);
template class RegionsCsvT<2>;
template class RegionsCsvT<3>;
template class BoxCsvT<2>;
template class BoxCsvT<3>;

}  // namespace dem::io
