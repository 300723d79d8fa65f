// The measures of a run's regions (output.region; dem/analysis) and the
// controlled box of an element test, as CSV tables written at the output
// interval (csv_file.h for number formats; docs/CASES.md describes every
// column):
//   regions.csv  2D: cycle,time,region,particles,rattlers,contacts,
//                    particle_contacts,sliding_contacts,sliding_fraction,
//                    coordination,mechanical_coordination,porosity,
//                    void_ratio,stress_xx,stress_xy,stress_yx,stress_yy,
//                    stress_1,stress_2,stress_angle,mean_stress,
//                    deviator_stress,sin_phi,tangential_share,fabric_xx,
//                    fabric_xy,fabric_yy,fabric_1,fabric_2,fabric_angle,
//                    anisotropy,weighted_fabric_xx,weighted_fabric_xy,
//                    weighted_fabric_yy,weighted_fabric_1,weighted_fabric_2,
//                    weighted_fabric_angle,weighted_anisotropy,fabric_trace,
//                    mean_normal_force,max_normal_force,mean_rotation,
//                    mean_abs_rotation
//                3D: the stress's nine components (stress_xx ... stress_zz),
//                    stress_1..3 and the major direction (stress_major_x,
//                    _y, _z) instead of the angle; the fabrics' six
//                    (fabric_xx, xy, xz, yy, yz, zz), their principal values
//                    and major directions likewise.
//                one row per region: stresses in Pa (per unit depth for
//                discs), compression positive; angles in rad from x,
//                counter-clockwise.
//   box.csv      cycle,time,extent_x,extent_y,(extent_z,)stress_x,...,
//                target_x,...,strain_x,...,volumetric_strain,
//                deviator_strain,mean_stress
//                while a box control is set (BoxMeasureT).
#pragma once

#include <filesystem>
#include <optional>
#include <vector>

#include "dem/analysis/region_measures.h"
#include "dem/io/csv_file.h"
#include "dem/world.h"

namespace dem::io {

template <int Dim>
class RegionsCsvT {
 public:
  // `resume`: a checkpoint's table sizes (csv_file.h).
  RegionsCsvT(const std::filesystem::path& directory, std::vector<analysis::RegionT<Dim>> regions,
              const TableSizes* resume = nullptr);
  // Measures every region and writes a row for each; returns the measures.
  std::vector<analysis::RegionMeasuresT<Dim>> write(const BasicWorld<Dim>& world);
  const std::filesystem::path& path() const { return file_.path(); }
  CsvFile& file() { return file_; }
  const std::vector<analysis::RegionT<Dim>>& regions() const { return regions_; }

 private:
  CsvFile file_;
  std::vector<analysis::RegionT<Dim>> regions_;
};

// The header and the numbers of a regions.csv row after cycle,time,region:
// shared with the service's table.
template <int Dim>
std::string region_columns();
template <int Dim>
std::vector<double> region_values(const analysis::RegionMeasuresT<Dim>& m);

template <int Dim>
class BoxCsvT {
 public:
  explicit BoxCsvT(const std::filesystem::path& directory, const TableSizes* resume = nullptr);
  void write(const BasicWorld<Dim>& world);  // a row when the world has a box control
  const std::filesystem::path& path() const { return file_.path(); }
  CsvFile& file() { return file_; }

 private:
  CsvFile file_;
};

extern template class RegionsCsvT<2>;
extern template class RegionsCsvT<3>;
extern template class BoxCsvT<2>;
extern template class BoxCsvT<3>;

}  // namespace dem::io
