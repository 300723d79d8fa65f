// The problems validation finds, with the checks many fields share
// (finite, > 0, >= 0, within an interval), each phrased the same way
// wherever it applies.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dem/case.pb.h"
#include "dem/io/case_validation.h"
#include "format_number.h"

namespace dem::io {

// A range of numbers whose ends may be open, as messages spell it: "(0, 1]".
struct Interval {
  double low = 0.0;
  double high = 0.0;
  bool low_open = false;
  bool high_open = false;

  std::string text() const {
    std::string text(1, low_open ? '(' : '[');
    text += format_number(low);
    text += ", ";
    text += format_number(high);
    text += high_open ? ')' : ']';
    return text;
  }
};

// Poisson's ratio of an isotropic elastic solid (positive shear and bulk moduli).
inline constexpr Interval kPoissonRatio{-1.0, 0.5, true, true};
// A coefficient of restitution: 1 is elastic; 0 has no logarithm (Miyata eq. 17).
inline constexpr Interval kRestitution{0.0, 1.0, true, false};

// The numbers a case may hold. Beyond 1e30 products in the force and
// energy arithmetic (stiffness x overlap, density x radius^3 x speed^2)
// overflow a double; a magnitude below 1e-30 other than 0 (a subnormal
// density such as 4.9e-324) makes masses and steps underflow to 0 and
// divisions by them infinite. No physical quantity in SI or in BALL's
// unitless numbers comes near either end.
inline constexpr double kLargestMagnitude = 1e30;
inline constexpr double kSmallestMagnitude = 1e-30;

// Why a probe's particle id is wrong, for validation and for conversion
// (which alone knows how many particles a csv_file source holds).
inline std::string no_particle_with_id(std::uint64_t id, std::uint64_t count) {
  return "no particle with id " + std::to_string(id) + " (the case defines " + std::to_string(count) + " particles" +
         (count > 0 ? ", ids 0 to " + std::to_string(count - 1) : "") + ")";
}

// Why a contact tolerance is too wide, for validation and for conversion
// (which alone reads the particle files' radii). BALL's TOL is a fraction
// of a radius. One beyond the largest diameter makes every pair within it
// a contact-table row: far apart particles by the million would make the
// table quadratic in their number.
inline std::optional<std::string> contact_tolerance_problem(double tolerance, double largest_radius) {
  if (!(tolerance > 2.0 * largest_radius)) return std::nullopt;
  return "must be at most the largest particle's diameter (" + format_number(2.0 * largest_radius) + " m), got " +
         format_number(tolerance) + " m; leave it out for a tenth of the mean radius";
}

// Each check returns whether the value passed, so callers can skip checks
// that build on it.
class ProblemList {
 public:
  void add(std::string path, std::string message) { list_.push_back({std::move(path), std::move(message)}); }

  bool finite(const std::string& path, double value) {
    if (!std::isfinite(value)) {
      add(path, "must be a finite number (got " + format_number(value) + ")");
      return false;
    }
    if (std::abs(value) > kLargestMagnitude) {
      add(path, "must be at most " + format_number(kLargestMagnitude) + " in magnitude (got " + format_number(value) +
                    "): numbers this large overflow the force arithmetic");
      return false;
    }
    return true;
  }

  bool finite(const std::string& path, const proto::Vector& v) {
    const bool x_ok = finite(path + ".x", v.x());
    const bool y_ok = finite(path + ".y", v.y());
    const bool z_ok = finite(path + ".z", v.z());
    return x_ok && y_ok && z_ok;
  }

  bool positive(const std::string& path, double value) {
    if (!finite(path, value)) return false;
    if (!(value > 0)) {
      add(path, "must be > 0 (got " + format_number(value) + ")");
      return false;
    }
    return not_tiny(path, value);
  }

  bool non_negative(const std::string& path, double value) {
    if (!finite(path, value)) return false;
    if (!(value >= 0)) {
      add(path, "must be >= 0 (got " + format_number(value) + ")");
      return false;
    }
    return value == 0 || not_tiny(path, value);
  }

  bool within(const std::string& path, double value, const Interval& interval) {
    if (!finite(path, value)) return false;
    const bool above = interval.low_open ? value > interval.low : value >= interval.low;
    const bool below = interval.high_open ? value < interval.high : value <= interval.high;
    if (above && below) return true;
    add(path, "must be in " + interval.text() + " (got " + format_number(value) + ")");
    return false;
  }

  // Whether a problem names the field: a check across fields builds on one
  // that passed its rule (case_rules.h).
  bool reported(const std::string& path) const {
    return std::ranges::any_of(list_, [&](const CaseProblem& problem) { return problem.path == path; });
  }

  std::vector<CaseProblem> take() { return std::move(list_); }

 private:
  bool not_tiny(const std::string& path, double value) {
    if (value >= kSmallestMagnitude) return true;
    add(path, "must be at least " + format_number(kSmallestMagnitude) + " (got " + format_number(value) +
                  "): numbers this small underflow masses and time steps to 0");
    return false;
  }

  std::vector<CaseProblem> list_;
};

}  // namespace dem::io
