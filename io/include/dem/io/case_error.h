// The one exception the conversion layer raises for a bad case: a file that
// cannot be read or parsed, a message that fails validation, or particles the
// generators cannot place. Each problem names the source, the line where it is
// known, the field and what is wrong; what() lists them one per line.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

namespace dem::io {

class CaseError : public std::runtime_error {
 public:
  explicit CaseError(std::vector<std::string> problems);
  explicit CaseError(const std::string& problem);

  // The same problems what() joins, for callers that report them one by one
  // (the service's error reply).
  const std::vector<std::string>& problems() const { return problems_; }

 private:
  std::vector<std::string> problems_;
};

}  // namespace dem::io
