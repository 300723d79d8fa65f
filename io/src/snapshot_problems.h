// The problems found in a snapshot message, each naming its field, and the
// checks of array lengths and finite numbers they come from.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace dem::io {

// Collects what is wrong with a message, each problem naming its field.
class Problems {
 public:
  void add(const std::string& path, const std::string& message) {
    if (list_.size() < kMaxListed) list_.push_back(path + ": " + message);
    ++count_;
  }
  bool empty() const { return count_ == 0; }
  std::string text() const {
    std::string out;
    for (const std::string& p : list_) out += (out.empty() ? "" : "\n") + p;
    if (count_ > list_.size()) out += "\n... and " + std::to_string(count_ - list_.size()) + " more problems";
    return out;
  }

 private:
  static constexpr std::size_t kMaxListed = 12;
  std::vector<std::string> list_;
  std::size_t count_ = 0;
};

// A packed array must hold `width` finite values for each of `count` items.
template <typename Values>
bool check_array(Problems& problems, const std::string& path, const Values& values, std::size_t count,
                 std::size_t item_width) {
  if (static_cast<std::size_t>(values.size()) != count * item_width) {
    problems.add(path, "has " + std::to_string(values.size()) + " values, expected " +
                           std::to_string(count * item_width) + " (" + std::to_string(item_width) + " for each of " +
                           std::to_string(count) + ")");
    return false;
  }
  for (int i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values.Get(i))) {
      problems.add(path + "[" + std::to_string(static_cast<std::size_t>(i) / item_width) + "]",
                   "is not a finite number");
      return false;
    }
  }
  return true;
}

template <typename Field>
bool check_length(Problems& problems, const std::string& path, const Field& values, std::size_t count) {
  if (static_cast<std::size_t>(values.size()) == count) return true;
  problems.add(path, "has " + std::to_string(values.size()) + " values, expected " + std::to_string(count));
  return false;
}

inline void check_finite(Problems& problems, const std::string& path, double value) {
  if (!std::isfinite(value)) problems.add(path, "is not a finite number");
}

inline bool in_range(std::int32_t id, std::size_t count) { return id >= 0 && static_cast<std::size_t>(id) < count; }

struct Counts {
  std::size_t particles = 0;
  // One past the highest particle id (ids stay with their particles, so
  // after a trim this exceeds `particles`).
  std::size_t particle_ids = 0;
  std::size_t walls = 0;
  std::size_t contacts = 0;
  std::size_t materials = 0;
};

}  // namespace dem::io
