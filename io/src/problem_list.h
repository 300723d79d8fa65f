// The problems validation finds, with the checks many fields share
// (finite, > 0, >= 0), each phrased the same way wherever it applies.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "dem/case.pb.h"
#include "dem/io/case_validation.h"
#include "format_number.h"

namespace dem::io {

// Each check returns whether the value passed, so callers can skip checks
// that build on it.
class ProblemList {
 public:
  void add(std::string path, std::string message) { list_.push_back({std::move(path), std::move(message)}); }

  bool finite(const std::string& path, double value) {
    if (std::isfinite(value)) return true;
    add(path, "must be a finite number (got " + format_number(value) + ")");
    return false;
  }

  bool finite(const std::string& path, const proto::Vector2& v) {
    const bool x_ok = finite(path + ".x", v.x());
    const bool y_ok = finite(path + ".y", v.y());
    return x_ok && y_ok;
  }

  bool positive(const std::string& path, double value) {
    if (!finite(path, value)) return false;
    if (value > 0) return true;
    add(path, "must be > 0 (got " + format_number(value) + ")");
    return false;
  }

  bool non_negative(const std::string& path, double value) {
    if (!finite(path, value)) return false;
    if (value >= 0) return true;
    add(path, "must be >= 0 (got " + format_number(value) + ")");
    return false;
  }

  std::vector<CaseProblem> take() { return std::move(list_); }

 private:
  std::vector<CaseProblem> list_;
};

}  // namespace dem::io
