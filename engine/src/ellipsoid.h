// Contact geometry of ellipsoids (Miyata et al. 2002, section 2.4; Lin &
// Ng 1995): f(x) = (x1/a1)^2 + (x2/a2)^2 + (x3/a3)^2 - 1 in the body's
// principal axes (eqs. 43-44). Between two bodies, the point of each
// surface that minimises the other's potential; the overlap is their
// distance along the contact normal, and the equivalent radius R_e comes
// from the principal curvatures of both surfaces there (eqs. 45-48). A
// face meets an ellipsoid at its support point (eqs. 50-56).
#pragma once

#include <array>

#include "dem/math.h"

namespace dem {

struct PlacedEllipsoid {
  Vec3 axes = Vec3::Ones();  // semi-axes a1, a2, a3, m
  Vec3 centre = Vec3::Zero();
  Quaternion orientation = Quaternion::Identity();  // body axes -> world
};

// A symmetric 3x3 matrix by its six entries: a product with one costs what
// a general one does, its cofactor inverse half.
struct SymmetricMatrix {
  double xx, xy, xz, yy, yz, zz;

  Vec3 operator*(const Vec3& v) const {
    return {xx * v.x() + xy * v.y() + xz * v.z(), xy * v.x() + yy * v.y() + yz * v.z(),
            xz * v.x() + yz * v.y() + zz * v.z()};
  }
  SymmetricMatrix plus(double s, const SymmetricMatrix& o) const {  // this + s o
    return {xx + s * o.xx, xy + s * o.xy, xz + s * o.xz, yy + s * o.yy, yz + s * o.yz, zz + s * o.zz};
  }
  SymmetricMatrix scaled(double s) const { return {s * xx, s * xy, s * xz, s * yy, s * yz, s * zz}; }
};

// An ellipsoid's matrices in world axes, worked out once per body and force
// pass and shared by all its contacts: its potential's M = R A^-2 R^T,
// f(x) = (x - c)^T M (x - c) - 1 (eqs. 43-44), and M^-1 = R A^2 R^T, whose
// quadratic form u^T M^-1 u is the square of how far the body reaches from
// its centre along the unit vector u.
struct EllipsoidFrame {
  SymmetricMatrix potential;
  SymmetricMatrix reach;
};
EllipsoidFrame ellipsoid_frame(const Vec3& axes, const Quaternion& orientation);
// Four bodies' frames at once, one in each lane of a vector: the same
// operations lane by lane, so the same bits as ellipsoid_frame.
void ellipsoid_frames(const std::array<Vec3, 4>& axes, const std::array<Quaternion, 4>& orientation,
                      EllipsoidFrame* out);

struct EllipsoidContact {
  double overlap;                     // > 0 in contact
  Vec3 normal;                        // from the first body towards the second
  Vec3 point;                         // halfway between the two surface points
  double effective_radius;            // R_e (see ellipsoid.cpp)
  Vec3 first_point, second_point;     // P_i on i (deepest in j's potential), P_j on j
  double multiplier_i, multiplier_j;  // where the searches ended: pass them back next cycle
};

// The contact between two ellipsoids; mu_i, mu_j start the searches (0:
// no previous value).
EllipsoidContact ellipsoid_contact(const EllipsoidFrame& i, const Vec3& centre_i, const EllipsoidFrame& j,
                                   const Vec3& centre_j, double mu_i = 0.0, double mu_j = 0.0);
EllipsoidContact ellipsoid_contact(const PlacedEllipsoid& i, const PlacedEllipsoid& j, double mu_i = 0.0,
                                   double mu_j = 0.0);

// One search of a batch: the two bodies' frames and centres (the second at
// its nearest image) and where the last cycle's searches ended.
struct EllipsoidQuery {
  const EllipsoidFrame* i;
  const EllipsoidFrame* j;
  Vec3 centre_i, centre_j;
  double mu_i = 0.0, mu_j = 0.0;
};

// ellipsoid_contact for each of `count` queries, several at a time across
// the lanes of a vector (each contact's two searches in two lanes, as
// ellipsoid_contact does them): the same operations lane by lane, so the
// same bits as one by one.
void ellipsoid_contacts(const EllipsoidQuery* queries, EllipsoidContact* out, int count);

// The contact of an ellipsoid with a plane through `on_plane` whose unit
// normal `towards` points to the ellipsoid's side: the support point P
// (eq. 54), its depth past the plane (eq. 55) and the projected point Q
// (eq. 56) to test against a face's outline.
struct EllipsoidFaceContact {
  double overlap;           // > 0 when P lies past the plane
  Vec3 support;             // P, on the ellipsoid
  Vec3 projected;           // Q, on the plane
  double effective_radius;  // sqrt(R' R'') of the ellipsoid at P
};
EllipsoidFaceContact ellipsoid_plane_contact(const EllipsoidFrame& body, const Vec3& centre, const Vec3& on_plane,
                                             const Vec3& towards);
EllipsoidFaceContact ellipsoid_plane_contact(const PlacedEllipsoid& body, const Vec3& on_plane, const Vec3& towards);

// Principal curvatures (1/m) of an ellipsoid's surface at a point on it.
Eigen::Vector2d ellipsoid_principal_curvatures(const PlacedEllipsoid& body, const Vec3& point);

// Mass per unit density and principal moments of inertia per unit density
// of a solid ellipsoid.
struct EllipsoidMass {
  double volume;
  Vec3 principal_moments;  // about a1, a2, a3: V/5 (a2^2 + a3^2), ...
};
EllipsoidMass ellipsoid_mass(const Vec3& axes);

}  // namespace dem
