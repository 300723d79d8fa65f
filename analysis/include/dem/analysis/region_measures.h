// The state of a region of an assembly, as Randall (1989) 4.6 and ch. 6
// read it: the average stress tensor from the contact forces and branch
// vectors, its part carried by normal and by tangential forces, the fabric
// tensor of the contact normals (4.45-4.54), porosity, coordination with
// and without rattlers, the share of sliding contacts, contact forces and
// particle rotations. Round particles (discs, spheres) only.
//
// Which particles and contacts count (the boundary treatment):
// - the stress sums over the particles whose centres lie in the region,
//   each with all its contacts (Barnes 1985 as Randall 4.2 reports it: "an
//   average of the individual stress tensors for each particle in the
//   sub-assembly"), over the volume those particles stand for:
//     sigma_ij = -(1 - n) / (depth sum_p A_p) sum_p sum_c (x_c - x_p)_i f_j,
//   f the force on p at contact point x_c, A_p its area (2D) or volume
//   (3D), n the region's porosity, so particles cut by the region's edge
//   count as a whole and the volume is what the region's solid fraction
//   says they fill; compression is positive. A regular packing filling the
//   region gives the boundary tractions exactly.
// - porosity clips every particle to the region exactly (areal in 2D, as
//   Randall's 14 % and 16 %).
// - coordination counts, for the particles whose centres lie in the region,
//   all their contacts (with particles and walls); rattlers are particles
//   left with fewer than two contacts once the rattlers among their
//   neighbours are taken away (repeated until none is left), anywhere in
//   the assembly.
// - the fabric, sliding, force and obliquity figures take the contacts
//   whose contact point lies in the region; the fabric and the sliding
//   share particle-particle contacts only (a wall contact's friction is
//   the wall's: frictionless walls would count as sliding).
#pragma once

#include <string>

#include "dem/analysis/assembly_sample.h"
#include "dem/analysis/principal.h"
#include "dem/analysis/region.h"

namespace dem::analysis {

// A fabric tensor (Randall 4.47-4.48) with its principal values and
// directions (4.52-4.54) and the degree of anisotropy f = Phi_1 - Phi_2
// (Thornton 1987a, Randall 6.5.2; in 3D major minus minor).
template <int Dim>
struct FabricT {
  Tensor<Dim> tensor = Tensor<Dim>::Zero();
  Principal<Dim> principal;
  double anisotropy = 0.0;
};

template <int Dim>
struct RegionMeasuresT {
  std::string region;
  double volume = 0.0;      // the region's area (2D) or volume (3D), m^2 or m^3
  double solid = 0.0;       // the particles' area or volume inside it
  double porosity = 0.0;    // 1 - solid / volume
  double void_ratio = 0.0;  // porosity / (1 - porosity)
  int particles = 0;        // centres inside
  int rattlers = 0;         // of those, rattlers
  int contacts = 0;         // contact points inside: particle-particle and particle-wall
  int particle_contacts = 0;
  int sliding_contacts = 0;              // particle-particle contacts at the Coulomb limit
  double sliding_fraction = 0.0;         // sliding_contacts / particle_contacts
  double coordination = 0.0;             // contacts per particle (centres inside)
  double mechanical_coordination = 0.0;  // the same without rattlers and their contacts
  // Stresses, Pa (N/m in 2D discs of unit thickness: per unit depth),
  // compression positive.
  Tensor<Dim> stress = Tensor<Dim>::Zero();
  Tensor<Dim> normal_stress = Tensor<Dim>::Zero();      // from the contacts' normal forces
  Tensor<Dim> tangential_stress = Tensor<Dim>::Zero();  // from their tangential forces
  Principal<Dim> principal_stress;
  double mean_stress = 0.0;      // trace / Dim
  double deviator_stress = 0.0;  // sigma_1 - sigma_Dim
  // The mobilised sin(phi) = (sigma_1 - sigma_Dim) / (sigma_1 + sigma_Dim) (Randall 6.4.2, 6.5.2).
  double sin_phi = 0.0;
  // The tangential forces' share of the deviator stress (Randall 6.5.2):
  // the tangential part's difference of normal stresses along the
  // principal directions of the whole stress, over sigma_1 - sigma_Dim.
  double tangential_share = 0.0;
  FabricT<Dim> fabric;             // Phi_ij = <n_i n_j> (4.47-4.48)
  FabricT<Dim> weighted_fabric;    // weighted to the normal force: sum N n_i n_j / sum N
  double fabric_trace = 0.0;       // F_kk = 2 M R / V (4.46): M contacts, R the mean radius, V the volume
  double mean_normal_force = 0.0;  // N, over the contacts inside
  double max_normal_force = 0.0;   // N
  double mean_rotation = 0.0;      // rad: 2D signed (counter-clockwise), 3D the mean angle
  double mean_abs_rotation = 0.0;  // rad
};

template <int Dim>
RegionMeasuresT<Dim> measure_region(const AssemblySampleT<Dim>& sample, const RegionT<Dim>& region);

// Which particles are rattlers (see above), by particle id.
template <int Dim>
std::vector<bool> find_rattlers(const AssemblySampleT<Dim>& sample);

// The box a kWhole region stands for: what the particles span, or the
// periodic cell along a periodic axis.
template <int Dim>
Box<Dim> whole_box(const AssemblySampleT<Dim>& sample);

// The contact point, in the periodic cell when the world repeats.
template <int Dim>
Vec<Dim> contact_point(const AssemblySampleT<Dim>& sample, const ContactRecordT<Dim>& contact);

using RegionMeasures = RegionMeasuresT<2>;
using RegionMeasures3 = RegionMeasuresT<3>;

}  // namespace dem::analysis
