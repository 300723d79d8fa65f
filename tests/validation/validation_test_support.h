// Shared by the validation tests: a fresh output directory for a check's
// CSV files, and a verdict printed and asserted.
#pragma once

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "verdict.h"

namespace dem::validation {

// <build>/tests/validation/out/<name>, emptied.
inline std::filesystem::path out_dir(const char* name) {
  const auto dir = std::filesystem::path(DEM_VALIDATION_TEST_OUTPUT) / name;
  std::filesystem::remove_all(dir);
  return dir;
}

// Prints every check under `title` and asserts that each held (and that
// there was one).
inline void expect_passed(const Verdict& verdict, const char* title) {
  verdict.print(stdout, title);
  EXPECT_TRUE(verdict.passed()) << verdict;
  EXPECT_FALSE(verdict.checks().empty());
}

}  // namespace dem::validation
