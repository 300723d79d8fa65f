#include "solid_volume.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace dem::analysis {

namespace {

constexpr double kPi = std::numbers::pi;

// The integral of sqrt(r^2 - u^2) from 0 to u, |u| <= r.
double half_chord_integral(double u, double r) {
  const double v = std::clamp(u / r, -1.0, 1.0);
  return 0.5 * r * r * (v * std::sqrt(1.0 - v * v) + std::asin(v));
}

// Gauss-Legendre nodes and weights on [-1, 1], 16 points.
constexpr std::array<double, 8> kNodes = {0.0950125098376374, 0.2816035507792589, 0.4580167776572274,
                                          0.6178762444026438, 0.7554044083550030, 0.8656312023878318,
                                          0.9445750230732326, 0.9894009349916499};
constexpr std::array<double, 8> kWeights = {0.1894506104550685, 0.1826034150449236, 0.1691565193950025,
                                            0.1495959888165767, 0.1246289712555339, 0.0951585116824928,
                                            0.0622535239386479, 0.0271524594117541};

template <typename F>
double gauss_legendre(F f, double a, double b) {
  const double middle = 0.5 * (a + b), half = 0.5 * (b - a);
  double sum = 0.0;
  for (std::size_t k = 0; k < kNodes.size(); ++k) {
    sum += kWeights[k] * (f(middle - half * kNodes[k]) + f(middle + half * kNodes[k]));
  }
  return sum * half;
}

}  // namespace

double disc_in_box(const Vec2& c, double r, const Box<2>& box) {
  // The area is the integral over x of the part of the disc's vertical
  // chord inside [y0, y1]. Between the x where the chord's ends cross y0 or
  // y1 (or the disc's edge or the box's sides), each end is either a box
  // side or the circle, so each piece integrates in closed form.
  const double x_low = std::max(box.min.x(), c.x() - r), x_high = std::min(box.max.x(), c.x() + r);
  if (x_low >= x_high) return 0.0;
  std::vector<double> breaks = {x_low, x_high};
  for (const double y : {box.min.y(), box.max.y()}) {
    const double d = y - c.y();
    if (std::abs(d) < r) {
      const double w = std::sqrt(r * r - d * d);
      for (const double x : {c.x() - w, c.x() + w}) {
        if (x > x_low && x < x_high) breaks.push_back(x);
      }
    }
  }
  std::sort(breaks.begin(), breaks.end());
  double area = 0.0;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = breaks[k], b = breaks[k + 1];
    if (b <= a) continue;
    const double m = 0.5 * (a + b) - c.x();
    const double h = std::sqrt(std::max(0.0, r * r - m * m));
    const bool top_is_box = box.max.y() < c.y() + h;
    const bool bottom_is_box = box.min.y() > c.y() - h;
    const double top = top_is_box ? box.max.y() : c.y() + h;
    const double bottom = bottom_is_box ? box.min.y() : c.y() - h;
    if (top <= bottom) continue;  // the chord misses the box over this piece
    const double chord = half_chord_integral(b - c.x(), r) - half_chord_integral(a - c.x(), r);
    const double upper = top_is_box ? box.max.y() * (b - a) : c.y() * (b - a) + chord;
    const double lower = bottom_is_box ? box.min.y() * (b - a) : c.y() * (b - a) - chord;
    area += upper - lower;
  }
  return area;
}

double disc_in_disc(const Vec2& c, double r, const Vec2& c2, double r2) {
  const double d = (c2 - c).norm();
  if (d >= r + r2) return 0.0;
  if (d <= std::abs(r2 - r)) return kPi * std::pow(std::min(r, r2), 2);
  // The lens: two circular segments cut by the common chord.
  const double a1 = std::acos(std::clamp((d * d + r * r - r2 * r2) / (2.0 * d * r), -1.0, 1.0));
  const double a2 = std::acos(std::clamp((d * d + r2 * r2 - r * r) / (2.0 * d * r2), -1.0, 1.0));
  return r * r * (a1 - 0.5 * std::sin(2.0 * a1)) + r2 * r2 * (a2 - 0.5 * std::sin(2.0 * a2));
}

double sphere_in_box(const Vec3& c, double r, const Box<3>& box) {
  // Slices along z: each a disc of radius sqrt(r^2 - (z - c_z)^2) in the
  // box's x-y rectangle, exact; their areas integrated by Gauss-Legendre on
  // pieces whose ends are where a slice's disc starts or stops reaching a
  // side or a corner of the rectangle, so each piece is smooth inside.
  const double z_low = std::max(box.min.z(), c.z() - r), z_high = std::min(box.max.z(), c.z() + r);
  if (z_low >= z_high) return 0.0;
  const Box<2> rectangle{box.min.head<2>(), box.max.head<2>()};
  const Vec2 centre = c.head<2>();
  std::vector<double> reach;  // slice radii where the area's formula changes
  for (const double x : {box.min.x(), box.max.x()}) reach.push_back(std::abs(x - c.x()));
  for (const double y : {box.min.y(), box.max.y()}) reach.push_back(std::abs(y - c.y()));
  for (const double x : {box.min.x(), box.max.x()}) {
    for (const double y : {box.min.y(), box.max.y()}) reach.push_back(std::hypot(x - c.x(), y - c.y()));
  }
  std::vector<double> breaks = {z_low, z_high};
  for (const double rho : reach) {
    if (rho >= r) continue;
    const double w = std::sqrt(r * r - rho * rho);
    for (const double z : {c.z() - w, c.z() + w}) {
      if (z > z_low && z < z_high) breaks.push_back(z);
    }
  }
  std::sort(breaks.begin(), breaks.end());
  const auto slice = [&](double z) {
    const double dz = z - c.z();
    return disc_in_box(centre, std::sqrt(std::max(0.0, r * r - dz * dz)), rectangle);
  };
  double volume = 0.0;
  for (std::size_t k = 0; k + 1 < breaks.size(); ++k) {
    const double a = breaks[k], b = breaks[k + 1];
    if (b <= a) continue;
    // The slices' area behaves like a square root of the distance to a
    // piece's ends; z = a + (b - a)(1 - cos(pi t)) / 2 makes the integrand
    // smooth in t, where Gauss-Legendre converges fast.
    const auto smoothed = [&](double t) {
      const double z = a + 0.5 * (b - a) * (1.0 - std::cos(kPi * t));
      return slice(z) * 0.5 * (b - a) * kPi * std::sin(kPi * t);
    };
    volume += gauss_legendre(smoothed, 0.0, 0.5) + gauss_legendre(smoothed, 0.5, 1.0);
  }
  return volume;
}

double sphere_in_sphere(const Vec3& c, double r, const Vec3& c2, double r2) {
  const double d = (c2 - c).norm();
  if (d >= r + r2) return 0.0;
  if (d <= std::abs(r2 - r)) return 4.0 / 3.0 * kPi * std::pow(std::min(r, r2), 3);
  // The lens of two spheres (two spherical caps).
  return kPi * std::pow(r + r2 - d, 2) * (d * d + 2.0 * d * (r + r2) - 3.0 * (r - r2) * (r - r2)) / (12.0 * d);
}

template <int Dim>
double solid_in_region(const Vec<Dim>& centre, double radius, const RegionT<Dim>& region, const Box<Dim>& whole) {
  switch (region.shape) {
    case RegionShape::kWhole:
      if constexpr (Dim == 2) {
        return disc_in_box(centre, radius, whole);
      } else {
        return sphere_in_box(centre, radius, whole);
      }
    case RegionShape::kBox:
      if constexpr (Dim == 2) {
        return disc_in_box(centre, radius, Box<2>{region.min, region.max});
      } else {
        return sphere_in_box(centre, radius, Box<3>{region.min, region.max});
      }
    case RegionShape::kBall:
      if constexpr (Dim == 2) {
        return disc_in_disc(centre, radius, region.centre, region.radius);
      } else {
        return sphere_in_sphere(centre, radius, region.centre, region.radius);
      }
  }
  return 0.0;
}

template double solid_in_region(const Vec2&, double, const RegionT<2>&, const Box<2>&);
template double solid_in_region(const Vec3&, double, const RegionT<3>&, const Box<3>&);

}  // namespace dem::analysis
