#include "verdict.h"

#include <cmath>

namespace dem::validation {
namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value);
  return text;
}

}  // namespace

void Verdict::expect(std::string name, bool passed, std::string detail) {
  checks_.push_back({std::move(name), passed, std::move(detail)});
}

void Verdict::near(std::string name, double measured, double expected, double tolerance) {
  expect(std::move(name), std::abs(measured - expected) <= tolerance,
         number(measured) + ", expected " + number(expected) + " within " + number(tolerance));
}

void Verdict::below(std::string name, double measured, double bound) {
  expect(std::move(name), measured < bound, number(measured) + ", expected below " + number(bound));
}

void Verdict::above(std::string name, double measured, double bound) {
  expect(std::move(name), measured > bound, number(measured) + ", expected above " + number(bound));
}

void Verdict::at_least(std::string name, double measured, double bound) {
  expect(std::move(name), measured >= bound, number(measured) + ", expected at least " + number(bound));
}

void Verdict::at_most(std::string name, double measured, double bound) {
  expect(std::move(name), measured <= bound, number(measured) + ", expected at most " + number(bound));
}

void Verdict::add(const Verdict& other) { checks_.insert(checks_.end(), other.checks_.begin(), other.checks_.end()); }

bool Verdict::passed() const { return failures() == 0; }

int Verdict::failures() const {
  int failed = 0;
  for (const Check& check : checks_) failed += check.passed ? 0 : 1;
  return failed;
}

void Verdict::print(std::FILE* out, const std::string& title) const {
  for (const Check& check : checks_) {
    std::fprintf(out, "  %s  %s: %s\n", check.passed ? "pass" : "FAIL", check.name.c_str(), check.detail.c_str());
  }
  if (passed()) {
    std::fprintf(out, "%s: PASS (%zu checks)\n", title.c_str(), checks_.size());
  } else {
    std::fprintf(out, "%s: FAIL (%d of %zu checks failed)\n", title.c_str(), failures(), checks_.size());
  }
}

std::ostream& operator<<(std::ostream& out, const Verdict& verdict) {
  for (const Check& check : verdict.checks()) {
    if (!check.passed) out << "failed: " << check.name << ": " << check.detail << '\n';
  }
  return out;
}

}  // namespace dem::validation
