// Contact geometry of 2D superquadrics (Miyata et al. 2002, section 2.3):
//   f(x, y) = (|x|/a)^n + (|y|/b)^n - 1   (eq. 34), 1 < n <= 10,
// with the boundary point P(alpha) = (a sgn(cos) |cos|^(2/n), b sgn(sin) |sin|^(2/n))
// (eq. 35). Contact between bodies i and j: the point of i's boundary that
// minimises j's function (eqs. 36-37; Newton steps in a smooth
// parametrisation of the same boundary, Brent's method where they cannot
// be trusted) and the point of j's
// boundary that minimises i's; their circles of curvature (eqs. 38-41) then
// overlap by rho_i + rho_j - |C_j - C_i| along the line C_i -> C_j (eq. 42).
//
// The force acts at the centroid of the region where the bodies overlap,
// not at P_i and P_j: on a flat side (n > 2) the minimising points are not
// unique - with n = 4 they run along the side as the cube root of a tilt,
// so a point force there turns a pair lying side on side with a moment
// whose stiffness grows without bound as the tilt vanishes, and the bodies
// rock (two flat-lying particles pressed together by a plate lose force
// in steps of 2-4 %). At the overlap's centroid a tilt theta moves the
// force by theta L^2 / (12 delta) over a side overlapping along L: the
// moment k theta L^2 / 12 of a linear spring spread over the side (Feng &
// Owen 2004 take the same point for polygons). On a curved contact the
// overlap is a thin lens about the line of centres of curvature, and its
// centroid the halfway point of eq. 42 to second order in the overlap.
#pragma once

#include "dem/math.h"

namespace dem {

struct Superquadric {
  double a = 1.0;  // semi-axis along the body's local x, m
  double b = 1.0;  // semi-axis along the body's local y, m
  double n = 2.0;  // shape exponent, 1 < n <= 10 (2 with a = b: a disc)
};

// A superquadric placed in the plane: centre and the angle of its local x axis.
struct PlacedSuperquadric {
  Superquadric shape;
  Vec2 centre = Vec2::Zero();
  double angle = 0.0;
};

// The radius of the smallest circle about the centre that holds the body:
// max(a, b) up to n = 2, more for squarer bodies (a square's corners reach
// a sqrt(2) as n grows). The broad phase and random packings use it.
double superquadric_bounding_radius(const Superquadric& s);

// f of eq. 34 at a point in the body's local frame.
double superquadric_function(const Superquadric& s, const Vec2& local);

// The boundary point of eq. 35 for the parametric angle alpha.
Vec2 superquadric_point(const Superquadric& s, double alpha);

// Radius of curvature (eq. 39) and outward unit normal (eq. 40) at a
// boundary point given in the local frame. The radius is capped at 1e3
// times the larger semi-axis: at the tip of a flat side (n > 2) the
// boundary is straight and the radius infinite.
struct Curvature {
  double radius;
  Vec2 normal;
};
Curvature superquadric_curvature(const Superquadric& s, const Vec2& local);

// The contact of eq. 42 between two placed superquadrics. Where the
// searches ended (the boundary points' directions from the centres, in
// each body's frame) is returned, and may be passed back in (alpha_i,
// alpha_j) to start the next search near them.
struct SuperquadricContact {
  double overlap;  // delta_n = rho_i + rho_j - d; > 0 in contact
  Vec2 normal;     // from C_i towards C_j
  Vec2 point;      // the centroid of the overlapping region: where the force acts
  double alpha_i, alpha_j;
  double radius_i, radius_j;       // the radii of curvature rho_i, rho_j
  Vec2 first_point, second_point;  // P_i and P_j in the plane
};
SuperquadricContact superquadric_contact(const PlacedSuperquadric& i, const PlacedSuperquadric& j, double alpha_i_hint,
                                         double alpha_j_hint, bool use_hints);

// The point of a placed superquadric deepest past a line whose unit normal
// `outward` points away from the body's side: its support point in the
// direction `outward`, and how far it lies past the line through `on_line`.
struct SupportContact {
  double overlap;  // > 0 when the body crosses the line
  Vec2 point;      // on the body's boundary
  double radius;   // its radius of curvature there
  // The centroid of the body's part past the line (the support point, at
  // no overlap): where the wall's force acts (the header's note).
  Vec2 centroid;
};
SupportContact superquadric_line_contact(const PlacedSuperquadric& body, const Vec2& on_line, const Vec2& outward);

// Area and polar moment of inertia per unit density (unit thickness) of a
// superquadric, integrated numerically once per particle.
struct SuperquadricMass {
  double area;
  double polar_moment;  // integral of (x^2 + y^2) dA
};
SuperquadricMass superquadric_mass(const Superquadric& s);

}  // namespace dem
