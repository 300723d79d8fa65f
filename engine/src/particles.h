// Particle state as structure-of-arrays, indexed by ParticleId. Hot data
// (positions, velocities, force sums) in parallel arrays; no per-particle
// objects. Written once over the dimension.
#pragma once

#include <cstddef>
#include <vector>

#include "dem/ids.h"
#include "dem/definitions.h"
#include "dem/math.h"

namespace dem {

// The particles' shape, one for the whole world so the contact passes
// choose their geometry once, like the law.
enum class ShapeKind { kRound, kSuperquadric, kEllipsoid };

template <int Dim>
struct Particles {
  // dynamic state
  std::vector<Vec<Dim>> position;          // x_i at cycle N
  std::vector<Vec<Dim>> velocity;          // x_dot_i at N - 1/2 (time-centred, eq. 22)
  std::vector<Spin<Dim>> angular_velocity;  // at N - 1/2 (eq. 23)
  std::vector<Orientation<Dim>> rotation;  // accumulated angle (2D) or unit quaternion (3D) (eq. 23a)
  // per-cycle sums (eqs. 20-21): contact forces and damping forces, moments
  std::vector<Vec<Dim>> force;
  std::vector<Spin<Dim>> moment;
  // |sum F| of the previous cycle, for the particle-wise critical step (Randall 4.38)
  std::vector<double> previous_force;
  // constant properties
  std::vector<double> radius;
  std::vector<double> mass;
  std::vector<double> inertia;  // about the centre (discs, spheres, superquadrics in the plane)
  std::vector<MaterialId> material;
  std::vector<ShapeDefT<Dim>> shape;  // superquadric or ellipsoid axes (the orientation lives in rotation)
  std::vector<Vec3> principal_inertia;  // ellipsoids: about their own axes (inertia holds the smallest)

  std::size_t size() const { return position.size(); }

  // omega^T I omega: with the scalar inertia for discs, spheres and
  // superquadrics, with the inertia tensor for ellipsoids.
  double spin_energy_product(std::size_t i, const Spin<Dim>& w) const {
    if constexpr (Dim == 3) {
      if (shape[i].ellipsoid()) {
        const Vec3 body = rotation[i].conjugate() * w;
        return body.dot(principal_inertia[i].cwiseProduct(body));
      }
      return inertia[i] * w.squaredNorm();
    } else {
      return inertia[i] * w * w;
    }
  }
};

}  // namespace dem
