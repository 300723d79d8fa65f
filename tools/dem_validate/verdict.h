// A validation's verdict: each check - what was measured against the bound
// the seed or the theory sets - and whether it holds. dem_validate prints
// it and exits 1 when a check fails; tests/validation asserts the same
// verdicts, so every bound is written once, here beside the runs.
#pragma once

#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace dem::validation {

struct Check {
  std::string name;  // what is checked: "sphere-wall V = 0.4 m/s: contact duration / Hertz's"
  bool passed = false;
  std::string detail;  // what was measured against what: "1.0031, expected 1 within 0.01"
};

class Verdict {
 public:
  void expect(std::string name, bool passed, std::string detail = {});
  void near(std::string name, double measured, double expected,
            double tolerance);                                     // |measured - expected| <= tolerance
  void below(std::string name, double measured, double bound);     // measured < bound
  void above(std::string name, double measured, double bound);     // measured > bound
  void at_least(std::string name, double measured, double bound);  // measured >= bound
  void at_most(std::string name, double measured, double bound);   // measured <= bound
  void add(const Verdict& other);

  bool passed() const;
  int failures() const;
  const std::vector<Check>& checks() const { return checks_; }
  // One line per check, then "TITLE: PASS (N checks)" or "TITLE: FAIL (K of N checks failed)".
  void print(std::FILE* out, const std::string& title) const;

 private:
  std::vector<Check> checks_;
};

// The failed checks, for a test's message.
std::ostream& operator<<(std::ostream& out, const Verdict& verdict);

}  // namespace dem::validation
