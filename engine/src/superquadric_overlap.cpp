#include "superquadric_overlap.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "superquadric_boundary.h"

namespace dem {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Points along each arc of the overlap's boundary: enough that the
// polygon's centroid lies within a small part of the overlap of the
// curved region's.
constexpr int kArcSegments = 6;

// t taken to within half a turn of t0.
double around(double t, double t0) { return t0 + std::remainder(t - t0, kTwoPi); }

double smaller_axis(const Superquadric& s) { return std::min(s.a, s.b); }
double larger_axis(const Superquadric& s) { return std::max(s.a, s.b); }

// How far from the contact point, along the tangent, to start looking for
// the overlap's ends: the half chord sqrt(2 rho delta) of a circle of the
// contact's radius of curvature, kept between a thousandth of the smaller
// semi-axis and the larger (a flat side's radius is capped far above it).
double expected_reach(double rho, double overlap, double smaller, double larger) {
  return std::clamp(std::sqrt(2.0 * rho * overlap), 1e-3 * smaller, larger);
}

// Where a function changes sign between a (negative) and b (positive):
// false position with the Illinois step.
template <typename G>
double crossing(const G& g, double a, double ga, double b, double gb) {
  for (int iteration = 0; iteration < 60 && std::abs(b - a) > 1e-10; ++iteration) {
    const double x = b - gb * (b - a) / (gb - ga);
    const double gx = g(x);
    if (gx == 0.0) return x;
    if ((gx > 0.0) == (gb > 0.0)) {
      b = x, gb = gx, ga *= 0.5;
    } else {
      a = b, ga = gb, b = x, gb = gx;
    }
  }
  return 0.5 * (a + b);
}

// The ends of the arc about t0 where g < 0 (g(t0) < 0): a first step out
// each way of `step`, doubled until g turns positive, then the crossing.
// False when none is found within half a turn.
template <typename G>
bool arc_ends(const G& g, double t0, double step, double& low, double& high) {
  const double g0 = g(t0);
  if (!(g0 < 0.0)) return false;
  for (const double direction : {-1.0, 1.0}) {
    double inside = t0, g_inside = g0, reach = step;
    for (;;) {
      const double outside = t0 + direction * reach;
      const double g_outside = g(outside);
      if (g_outside > 0.0) {
        (direction < 0.0 ? low : high) = crossing(g, inside, g_inside, outside, g_outside);
        break;
      }
      inside = outside, g_inside = g_outside;
      reach *= 2.0;
      if (reach > std::numbers::pi) return false;
    }
  }
  return true;
}

// A point of the plane on both bodies' boundaries, by Newton's method on
// (f_i, f_j) = 0 from `point`, no step longer than max_step.
std::optional<Vec2> meeting_point(const PlacedSuperquadric& i, const Turn& turn_i, const PlacedSuperquadric& j,
                                  const Turn& turn_j, Vec2 point, double max_step) {
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Level li = level(i, turn_i, point), lj = level(j, turn_j, point);
    const Vec2 &gi = li.gradient, &gj = lj.gradient;
    const double determinant = gi.x() * gj.y() - gi.y() * gj.x();
    if (!(std::abs(determinant) > 0.0)) return std::nullopt;
    Vec2 step(-(li.value * gj.y() - lj.value * gi.y()) / determinant,
              -(gi.x() * lj.value - gj.x() * li.value) / determinant);
    const double length = step.norm();
    if (length > max_step) step *= max_step / length;
    point += step;
    if (length < 1e-12 * max_step) return point;
  }
  return std::nullopt;
}

// The points of a placed body's boundary from radial parameter `from` to
// `to`, kArcSegments + 1 of them, into corners (the parameter turned by
// products, not a cosine and sine each).
Vec2* arc_points(const PlacedSuperquadric& body, const Turn& turn, double from, double to, Vec2* corners) {
  const double step = (to - from) / kArcSegments;
  const double cos_step = std::cos(step), sin_step = std::sin(step);
  double c = std::cos(from), s = std::sin(from);
  for (int k = 0; k <= kArcSegments; ++k) {
    *corners++ = body.centre + turn(radial_point(body.shape, c, s));
    const double turned = c * cos_step - s * sin_step;
    s = s * cos_step + c * sin_step;
    c = turned;
  }
  return corners;
}

// The centroid of a polygon given by its corners in order, relative to
// `origin` for round-off; none when it has no area.
std::optional<Vec2> polygon_centroid(const Vec2* corners, int count, const Vec2& origin) {
  double area2 = 0.0;
  Vec2 moment = Vec2::Zero();
  for (int k = 0; k < count; ++k) {
    const Vec2 p = corners[k] - origin, q = corners[(k + 1) % count] - origin;
    const double cross = p.x() * q.y() - q.x() * p.y();
    area2 += cross;
    moment += cross * (p + q);
  }
  if (!(std::abs(area2) > 0.0)) return std::nullopt;
  return Vec2(origin + moment / (3.0 * area2));
}

// A body's radial parameters of two points on its boundary, taken about t0
// (a parameter between them) and put in order; false when t0 is not
// between them.
bool arc_between(const PlacedSuperquadric& body, const Turn& turn, const Vec2& a, const Vec2& b, double t0, double& low,
                 double& high) {
  const double ta = around(radial_parameter(body.shape, turn.inverse()(a - body.centre)), t0);
  const double tb = around(radial_parameter(body.shape, turn.inverse()(b - body.centre)), t0);
  low = std::min(ta, tb), high = std::max(ta, tb);
  return low < t0 && t0 < high;
}

// The overlap's two meeting points by the boundaries' parameters when
// Newton's method does not find them: i's arc inside j bracketed and its
// ends found by false position.
bool meeting_points_by_arc(const PlacedSuperquadric& i, const Turn& turn_i, const PlacedSuperquadric& j,
                           const Turn& turn_j, const SuperquadricContact& contact, double t_i, Vec2& a, Vec2& b) {
  const Turn relative = turn_i.minus(turn_j);
  const Vec2 offset = turn_j.inverse()(i.centre - j.centre);
  const auto inside_j = [&](double t) {
    return superquadric_function(j.shape, relative(radial_point(i.shape, std::cos(t), std::sin(t))) + offset);
  };
  const Vec2 p = radial_point(i.shape, std::cos(t_i), std::sin(t_i));
  const double step = std::clamp(std::sqrt(2.0 * contact.radius_i * contact.overlap) / p.norm(), 1e-4, 0.5);
  double low = t_i, high = t_i;
  if (!arc_ends(inside_j, t_i, step, low, high)) return false;
  a = i.centre + turn_i(radial_point(i.shape, std::cos(low), std::sin(low)));
  b = i.centre + turn_i(radial_point(i.shape, std::cos(high), std::sin(high)));
  return true;
}

}  // namespace

std::optional<Vec2> overlap_centroid(const PlacedSuperquadric& i, const PlacedSuperquadric& j,
                                     const SuperquadricContact& contact, double t_i, double t_j) {
  const Turn turn_i(i.angle), turn_j(j.angle);
  const Vec2 tangent(-contact.normal.y(), contact.normal.x());
  const double smaller = std::min(smaller_axis(i.shape), smaller_axis(j.shape));
  const double larger = std::max(larger_axis(i.shape), larger_axis(j.shape));
  const double reach = expected_reach(std::min(contact.radius_i, contact.radius_j), contact.overlap, smaller, larger);
  const auto a = meeting_point(i, turn_i, j, turn_j, contact.point - reach * tangent, 0.5 * smaller);
  const auto b = meeting_point(i, turn_i, j, turn_j, contact.point + reach * tangent, 0.5 * smaller);
  Vec2 first, second;
  if (a && b && (*a - contact.point).dot(tangent) < 0.0 && (*b - contact.point).dot(tangent) > 0.0) {
    first = *a, second = *b;
  } else if (!meeting_points_by_arc(i, turn_i, j, turn_j, contact, t_i, first, second)) {
    return std::nullopt;
  }
  // i's arc inside j, then j's arc inside i, each in its own
  // counter-clockwise sense: the overlap's boundary once round.
  double i_low, i_high, j_low, j_high;
  if (!arc_between(i, turn_i, first, second, t_i, i_low, i_high) ||
      !arc_between(j, turn_j, first, second, t_j, j_low, j_high)) {
    return std::nullopt;
  }
  Vec2 corners[2 * (kArcSegments + 1)];
  arc_points(j, turn_j, j_low, j_high, arc_points(i, turn_i, i_low, i_high, corners));
  return polygon_centroid(corners, 2 * (kArcSegments + 1), contact.point);
}

std::optional<Vec2> line_overlap_centroid(const PlacedSuperquadric& body, const Vec2& on_line, const Vec2& outward,
                                          const SupportContact& support) {
  const Turn turn(body.angle);
  const Vec2 along(-outward.y(), outward.x());
  const Vec2 foot = support.point - support.overlap * outward;  // the support point's foot on the line
  const double smaller = smaller_axis(body.shape), larger = larger_axis(body.shape);
  // Where the boundary crosses the line, as a distance along it from the
  // foot: Newton's method on f along the line.
  const auto crossing_along = [&](double s) -> std::optional<double> {
    const double max_step = 0.25 * smaller;
    for (int iteration = 0; iteration < 50; ++iteration) {
      const Level l = level(body, turn, foot + s * along);
      const double slope = l.gradient.dot(along);
      if (!(std::abs(slope) > 0.0)) return std::nullopt;
      const double step = std::clamp(-l.value / slope, -max_step, max_step);
      s += step;
      if (std::abs(step) < 1e-12 * max_step) return s;
    }
    return std::nullopt;
  };
  const double reach = expected_reach(support.radius, support.overlap, smaller, larger);
  const double t0 = radial_parameter(body.shape, turn.inverse()(support.point - body.centre));
  const auto a = crossing_along(-reach), b = crossing_along(reach);
  Vec2 first, second;
  if (a && b && *a < 0.0 && *b > 0.0) {
    first = foot + *a * along, second = foot + *b * along;
  } else {
    const auto past_line = [&](double t) {
      return -(body.centre + turn(radial_point(body.shape, std::cos(t), std::sin(t))) - on_line).dot(outward);
    };
    const Vec2 local = turn.inverse()(support.point - body.centre);
    const double step = std::clamp(std::sqrt(2.0 * support.radius * support.overlap) / local.norm(), 1e-4, 0.5);
    double low = t0, high = t0;
    if (!arc_ends(past_line, t0, step, low, high)) return std::nullopt;
    first = body.centre + turn(radial_point(body.shape, std::cos(low), std::sin(low)));
    second = body.centre + turn(radial_point(body.shape, std::cos(high), std::sin(high)));
  }
  double low, high;
  if (!arc_between(body, turn, first, second, t0, low, high)) return std::nullopt;
  // The arc past the line, closed by the line.
  Vec2 corners[kArcSegments + 1];
  arc_points(body, turn, low, high, corners);
  return polygon_centroid(corners, kArcSegments + 1, support.point);
}

}  // namespace dem
