// Where two bodies touch: the overlap, the normal e_i, the contact point and
// the lever arms from each centre, for round particles (Cundall & Strack
// eqs. 8-10) and for 2D superquadrics (Miyata et al. 2002, eqs. 34-42).
// A shape policy is chosen once per pass, like the contact law.
#pragma once

#include <cmath>

#include "contact_table.h"
#include "ellipsoid.h"
#include "particles.h"
#include "pass_inputs.h"
#include "periodic.h"
#include "superquadric.h"
#include "walls.h"

namespace dem {

template <int Dim>
struct ContactGeometry {
  double overlap = 0.0;                // > 0 in contact
  Vec<Dim> normal = Vec<Dim>::Zero();  // e_i, from the first body towards the second
  Vec<Dim> point = Vec<Dim>::Zero();   // halfway through the overlap
  // From each centre to its own surface point of the contact: the lever of
  // the contact force, as BALL takes it (Sum M = F_s R for a disc).
  Vec<Dim> arm_first = Vec<Dim>::Zero();
  Vec<Dim> arm_second = Vec<Dim>::Zero();  // 0 for a wall
  double effective_radius = 0.0;           // R* for the Hertz laws
};

// Discs and spheres: the line of centres (eqs. 8-10). Their moments keep
// BALL's form F_s R (tangential.h), so `round` tells the passes which.
//
// Most rows of a dense table are neighbours within the tolerance that do not
// touch: their squared distance tells them apart without a root, and they
// get no more geometry unless `kApartGeometry` asks for it (the energy
// budget settles the work of a contact that has just separated).
struct RoundShape {
  static constexpr bool round = true;

  template <bool kApartGeometry, int Dim>
  static ContactGeometry<Dim> pair(const PassInputs<Dim>& in, Slot x, Slot y, ContactSearch&) {
    const Particles<Dim>& p = in.particles;
    const Vec<Dim> d = in.periodic.separation(p.position[x], p.position[y]);
    const double rx = p.radius[x], ry = p.radius[y];
    const double distance2 = d.squaredNorm();
    if (!kApartGeometry && distance2 >= (rx + ry) * (rx + ry)) {
      ContactGeometry<Dim> g;
      g.overlap = -1.0;
      return g;
    }
    return geometry(d, distance2, rx, ry, p.position[x]);
  }

  // From the separation d of the centres (first to second) and its square.
  template <int Dim>
  [[gnu::always_inline]] static ContactGeometry<Dim> geometry(const Vec<Dim>& d, double distance2, double rx, double ry,
                                                              const Vec<Dim>& first_centre) {
    ContactGeometry<Dim> g;
    const double distance = std::sqrt(distance2);
    const bool apart = !(distance > 0.0);  // centres on each other: no normal, no contact
    const double inverse = 1.0 / distance;
    g.overlap = apart ? -1.0 : rx + ry - distance;                                              // eq. 8
    for (int k = 0; k < Dim; ++k) g.normal[k] = apart ? (k == 0 ? 1.0 : 0.0) : d[k] * inverse;  // eq. 9
    g.point = first_centre + (rx - 0.5 * g.overlap) * g.normal;
    g.arm_first = rx * g.normal;
    g.arm_second = -ry * g.normal;
    g.effective_radius = rx * ry / (rx + ry);  // Randall 4.5
    return g;
  }

  template <int Dim>
  static ContactGeometry<Dim> wall(const PassInputs<Dim>& in, const WallDefT<Dim>& wall, Slot x) {
    ContactGeometry<Dim> g;
    const Vec<Dim>& centre = in.particles.position[x];
    const double r = in.particles.radius[x];
    // The wall point A_(w) on the perpendicular through the particle centre (Fig. 1).
    const Vec<Dim> q = closest_point(wall, centre).point;
    const Vec<Dim> d = q - centre;
    const double distance = d.norm();
    g.overlap = r - distance;
    // e points from the particle to the wall; a centre exactly on the wall
    // takes the wall's normal towards the particle side, reversed.
    g.normal = distance > 0.0 ? Vec<Dim>(d / distance) : Vec<Dim>(-wall_normal(wall));
    g.point = centre + (r - 0.5 * g.overlap) * g.normal;  // halfway between A_(D) and A_(w)
    g.arm_first = r * g.normal;
    g.effective_radius = r;
    return g;
  }
};

// Most rows of the contact table are neighbours within the tolerance that do
// not touch. A shaped particle lies inside the circle or sphere of its
// largest semi-axis (its radius), so when those do not meet there is no
// contact and the iterative search is skipped; it then starts afresh when
// they meet again, whatever came before.
template <int Dim>
bool bounding_circles_meet(const Particles<Dim>& p, Slot x, Slot y, const Vec<Dim>& d, ContactSearch& search) {
  const double reach = p.radius[x] + p.radius[y];
  if (d.squaredNorm() < reach * reach) return true;
  search.valid = false;
  return false;
}

// No contact: the gap between the bounding circles, as a negative overlap.
template <int Dim>
ContactGeometry<Dim> apart(const Particles<Dim>& p, Slot x, Slot y, const Vec<Dim>& d) {
  ContactGeometry<Dim> g;
  g.overlap = p.radius[x] + p.radius[y] - d.norm();
  g.normal = d.normalized();
  return g;
}

// 2D superquadrics: the circles of curvature at the points that minimise
// each other's potential (eqs. 34-42), warm-started from the last cycle;
// the force acts at the overlap's centroid (superquadric.h).
struct SuperquadricShape {
  static constexpr bool round = false;

  static PlacedSuperquadric placed(const Particles<2>& p, Slot i, const Vec2& centre) {
    const ShapeDefT<2>& s = p.shape[i];
    return {{s.a, s.b, s.n}, centre, p.rotation[i]};
  }

  template <bool>
  static ContactGeometry<2> pair(const PassInputs<2>& in, Slot x, Slot y, ContactSearch& search) {
    const Particles<2>& p = in.particles;
    const Vec2& cx = p.position[x];
    const Vec2 d = in.periodic.separation(cx, p.position[y]);
    if (!bounding_circles_meet(p, x, y, d, search)) return apart(p, x, y, d);
    const Vec2 cy = cx + d;  // the nearest image of y
    const SuperquadricContact c =
        superquadric_contact(placed(p, x, cx), placed(p, y, cy), search.first, search.second, search.valid);
    search = {c.alpha_i, c.alpha_j, true};
    ContactGeometry<2> g;
    g.overlap = c.overlap;
    g.normal = c.normal;
    g.point = c.point;
    g.arm_first = c.point - cx;
    g.arm_second = c.point - cy;
    g.effective_radius = c.radius_i * c.radius_j / (c.radius_i + c.radius_j);
    return g;
  }

  static ContactGeometry<2> wall(const PassInputs<2>& in, const WallDefT<2>& wall, Slot x) {
    const Particles<2>& p = in.particles;
    ContactGeometry<2> g;
    const Vec2 towards_particles = wall_normal(wall);
    const SupportContact s = superquadric_line_contact(placed(p, x, p.position[x]), wall.point, -towards_particles);
    // The deepest point must lie along the segment; past its ends there is no contact.
    const double along = (s.point - wall.point).dot(wall.direction);
    g.overlap = along >= wall.h1 && along <= wall.h2 ? s.overlap : -1.0;
    g.normal = -towards_particles;
    g.point = s.centroid;
    g.arm_first = s.centroid - p.position[x];
    g.effective_radius = s.radius;
    return g;
  }
};

// Ellipsoids: the points of each surface deepest in the other's potential,
// warm-started from the last cycle (Miyata 2.4), and the support point
// against a rectangular wall, which must fall inside it (eqs. 51-59).
struct EllipsoidShape {
  static constexpr bool round = false;

  template <bool kApartGeometry>
  static ContactGeometry<3> pair(const PassInputs<3>& in, Slot x, Slot y, ContactSearch& search) {
    ContactGeometry<3> g;
    EllipsoidQuery q;
    if (!screen<kApartGeometry>(in, x, y, search, g, q)) return g;
    const EllipsoidContact c = ellipsoid_contact(*q.i, q.centre_i, *q.j, q.centre_j, q.mu_i, q.mu_j);
    search = {c.multiplier_i, c.multiplier_j, true};
    return geometry(c, q.centre_i, q.centre_j);
  }

  // What comes before the search: false, with `g` the row's geometry, when
  // the bounding spheres or the supports tell the bodies apart; else true,
  // with `q` the search to make (ellipsoid_rows.h makes several at once).
  template <bool kApartGeometry>
  [[gnu::always_inline]] static bool screen(const PassInputs<3>& in, Slot x, Slot y, ContactSearch& search,
                                            ContactGeometry<3>& g, EllipsoidQuery& q) {
    const Particles<3>& p = in.particles;
    const Vec3& cx = p.position[x];
    const Vec3 d = in.periodic.separation(cx, p.position[y]);
    // Most rows are neighbours apart: they get no root and no normal
    // unless kApartGeometry asks (see RoundShape).
    if (!bounding_circles_meet(p, x, y, d, search)) {
      if (kApartGeometry) {
        g = apart(p, x, y, d);
      } else {
        g = ContactGeometry<3>{};
        g.overlap = -1.0;
      }
      return false;
    }
    // An elongated body's bounding sphere reaches far past it. How far each
    // reaches along the line of centres (its support) tells most pairs
    // whose spheres meet apart: the plane across that line between the two
    // supports separates them. sqrt(d^T M^-1 d) is a body's reach times |d|.
    const EllipsoidFrame& fx = in.ellipsoid_frames[x];
    const EllipsoidFrame& fy = in.ellipsoid_frames[y];
    const double reach_times_distance = std::sqrt(d.dot(fx.reach * d)) + std::sqrt(d.dot(fy.reach * d));
    const double distance2 = d.squaredNorm();
    if (reach_times_distance < distance2) {
      g = ContactGeometry<3>{};
      g.overlap = -1.0;
      if (kApartGeometry) {
        const double distance = std::sqrt(distance2);
        g.overlap = reach_times_distance / distance - distance;
        g.normal = d / distance;
      }
      return false;
    }
    // With the nearest image of y.
    q = {&fx, &fy, cx, cx + d, search.valid ? search.first : 0.0, search.valid ? search.second : 0.0};
    return true;
  }

  // A row's geometry from its search, cx and cy the centres searched.
  static ContactGeometry<3> geometry(const EllipsoidContact& c, const Vec3& cx, const Vec3& cy) {
    ContactGeometry<3> g;
    g.overlap = c.overlap;
    g.normal = c.normal;
    g.point = c.point;
    g.arm_first = c.first_point - cx;
    g.arm_second = c.second_point - cy;
    g.effective_radius = c.effective_radius;
    return g;
  }

  static ContactGeometry<3> wall(const PassInputs<3>& in, const WallDefT<3>& wall, Slot x) {
    if (!wall.triangles.empty()) return faces(in, wall, x);
    const Particles<3>& p = in.particles;
    ContactGeometry<3> g;
    const Vec3 towards_particles = wall_normal(wall);
    const EllipsoidFaceContact c =
        ellipsoid_plane_contact(in.ellipsoid_frames[x], p.position[x], wall.point, towards_particles);
    // The projected point must fall inside the rectangle (eqs. 57-59 for a
    // triangle; its two coordinates here); past its edges there is no contact.
    const Vec3 d = c.projected - wall.point;
    const double s = d.dot(wall.direction), t = d.dot(wall.direction2);
    const bool inside = s >= wall.h1 && s <= wall.h2 && t >= wall.k1 && t <= wall.k2;
    g.overlap = inside ? c.overlap : -1.0;
    g.normal = -towards_particles;
    g.point = c.support + 0.5 * c.overlap * towards_particles;
    g.arm_first = c.support - p.position[x];
    g.effective_radius = c.effective_radius;
    return g;
  }

  // A wall of triangle faces: each face's plane, turned towards the
  // particle, gives a support point; the contact holds when its projection
  // falls inside the face (eq. 59), and the deepest such face is the
  // contact. A point on the edge two faces share has a zero coordinate (to
  // round-off) in both, so the edge counts as inside: with eq. 59's strict
  // > 0 a particle centred over the seam would touch neither face.
  static ContactGeometry<3> faces(const PassInputs<3>& in, const WallDefT<3>& wall, Slot x) {
    constexpr double kOnTheEdge = 1e-12;  // triangular coordinates are area fractions
    const Particles<3>& p = in.particles;
    ContactGeometry<3> g;
    g.overlap = -1.0;
    const EllipsoidFrame& body = in.ellipsoid_frames[x];
    for (const auto& t : wall.triangles) {
      Vec3 towards = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
      if ((p.position[x] - t[0]).dot(towards) < 0.0) towards = -towards;
      const EllipsoidFaceContact c = ellipsoid_plane_contact(body, p.position[x], t[0], towards);
      if (c.overlap <= g.overlap || (triangular_coordinates(t, c.projected).array() < -kOnTheEdge).any()) continue;
      g.overlap = c.overlap;
      g.normal = -towards;
      g.point = c.support + 0.5 * c.overlap * towards;
      g.arm_first = c.support - p.position[x];
      g.effective_radius = c.effective_radius;
    }
    return g;
  }
};

}  // namespace dem
