// What the measures of a region read, as plain data: the particles (round:
// discs or spheres) and every touching contact as the last force pass left
// it. A test builds one by hand; sample() copies it from a world. The
// arrays are by position in the sample, and the contacts name particles by
// that position: the world's ids keep gaps after a trim (world.h), `ids`
// holds them.
#pragma once

#include <vector>

#include "dem/definitions.h"
#include "dem/measures.h"
#include "dem/world.h"

namespace dem::analysis {

template <int Dim>
struct AssemblySampleT {
  std::vector<Vec<Dim>> position;  // m
  std::vector<ParticleId> ids;     // the world's id of each particle (sample() only)
  std::vector<double> radius;      // m
  // The angle each particle has turned through since the world was built,
  // rad: the accumulated angle (2D, counter-clockwise positive) or the
  // angle of its rotation quaternion (3D, >= 0).
  std::vector<double> rotation;
  std::vector<ContactRecordT<Dim>> contacts;  // touching contacts; each acts on `first` with `force`
  // 2D: the out-of-plane depth that turns areas into volumes for the
  // stress (1 for discs, the mean diameter for spheres in the plane;
  // Randall 1989, 4.4). 3D: 1.
  double depth = 1.0;
  PeriodicDefT<Dim> periodic;

  std::size_t particle_count() const { return position.size(); }
};

template <int Dim>
AssemblySampleT<Dim> sample(const BasicWorld<Dim>& world);

using AssemblySample = AssemblySampleT<2>;
using AssemblySample3 = AssemblySampleT<3>;

}  // namespace dem::analysis
