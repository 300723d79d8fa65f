// The average strain of a region between two states of an assembly: the
// "average ... strain tensors for a specified circular region" of BALL's
// analysis routines that Randall (1989) used (2.3; his measurement circles
// of 6.4.2 and 6.5.2, whose volumetric strain Fig. 6.8 plots). The thesis
// names the measure without its formula; here it is the displacement
// gradient that best fits the displacements of the particles whose
// centres lay inside the region in the reference state (least squares):
//   u_p ~ u_0 + G (X_p - X_mean),  G = (sum u'_p X'_p^T)(sum X'_p X'_p^T)^-1
// with X' and u' the reference positions and the displacements less their
// means. A homogeneous deformation is read exactly, a rigid translation
// gives zero; the small strain is the symmetric part of G (a rigid
// rotation's skew part drops out), compression positive as the stresses.
// Particles are matched by their world ids; those absent from the current
// state (a trim) are left out. Round particles and other shapes alike: only
// the centres count.
#pragma once

#include "dem/analysis/assembly_sample.h"
#include "dem/analysis/principal.h"
#include "dem/analysis/region.h"

namespace dem::analysis {

template <int Dim>
struct RegionStrainT {
  int particles = 0;                                        // centres inside the region in the reference state
  Tensor<Dim> displacement_gradient = Tensor<Dim>::Zero();  // G = du/dX
  // eps = -(G + G^T) / 2: compression positive (Randall's strains).
  Tensor<Dim> strain = Tensor<Dim>::Zero();
  Principal<Dim> principal;   // of the strain, major (most compressive) first
  double volumetric = 0.0;    // trace: contraction positive
  double deviator = 0.0;      // eps_1 - eps_Dim
  double rotation = 0.0;      // 2D: the skew part, rad counter-clockwise (G_yx - G_xy) / 2; 3D: 0
  double fit_residual = 0.0;  // rms of what the fitted field leaves of the displacements, m
};

// Throws std::invalid_argument when fewer than Dim + 1 particles of the
// region are found in both states or their reference centres lie on a
// line (a plane in 3D): no gradient can be fitted.
template <int Dim>
RegionStrainT<Dim> measure_region_strain(const AssemblySampleT<Dim>& reference, const AssemblySampleT<Dim>& current,
                                         const RegionT<Dim>& region);

using RegionStrain = RegionStrainT<2>;
using RegionStrain3 = RegionStrainT<3>;

}  // namespace dem::analysis
