// Whether an assembly is being deformed quasi-statically: the measures of
// AssemblyMeasures that compare its motion with the forces that hold it
// (docs/CASES.md, "Quasi-static measures"). Miyata et al. (2002) 3.2-3.3
// load "small enough for the system to maintain quasi-static behavior";
// these say whether a run did.
#pragma once

#include "dem/measures.h"
#include "world_state.h"

namespace dem {

// The spread of the principal rates of deformation of the particles' best
// linear velocity field, v = v0 + L (x - x0) fitted by least squares over
// the axes that do not repeat (a periodic cell keeps its period, so it
// does not deform along them): lambda_max(D) - lambda_min(D) with D the
// symmetric part of L. It is the shear rate of a simple shear and the strain
// rate of a uniaxial compression; 1/s.
template <int Dim>
double deformation_rate(const Particles<Dim>& particles, const Periodic<Dim>& periodic);

// The Love-Weber mean stress over the volume the particles span (along a
// periodic axis, the period), compression positive, Pa (per unit depth for
// 2D discs): p = -1/(Dim V) sum over contacts of the force on each body
// dotted with the arm from its centre to the contact point.
template <int Dim>
double mean_stress(const WorldState<Dim>& state);

// The mean volume-equivalent diameter (m) and the solid density (kg/m^3,
// total mass over total solid volume) of the particles.
struct GrainScale {
  double diameter = 0.0;
  double density = 0.0;
};
template <int Dim>
GrainScale grain_scale(const WorldState<Dim>& state);

// The inertial number I = rate d / sqrt(p / rho) (GDR MiDi 2004; below about
// 1e-3 a flow is quasi-static): 0 when nothing deforms, infinite when a
// deforming assembly holds no stress.
double inertial_number(double rate, const GrainScale& grains, double mean_stress);

}  // namespace dem
