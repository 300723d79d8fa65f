#include "dem/io/case_error.h"

#include <utility>

namespace dem::io {
namespace {

std::string join_lines(const std::vector<std::string>& lines) {
  std::string joined;
  for (const std::string& line : lines) {
    if (!joined.empty()) joined += '\n';
    joined += line;
  }
  return joined;
}

}  // namespace

CaseError::CaseError(std::vector<std::string> problems)
    : std::runtime_error(join_lines(problems)), problems_(std::move(problems)) {}

CaseError::CaseError(const std::string& problem) : CaseError(std::vector<std::string>{problem}) {}

}  // namespace dem::io
