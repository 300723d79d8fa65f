#include "snapshot_checks.h"

#include <google/protobuf/descriptor.h>
#include <google/protobuf/reflection.h>

#include <cmath>
#include <map>

#include "format_number.h"
#include "problem_list.h"

namespace dem::io {
namespace {

using google::protobuf::FieldDescriptor;
using google::protobuf::Message;
using Problems = std::vector<std::pair<std::string, std::string>>;

// Stops after this many of one kind, as the conversion's own list does:
// a corrupt array would otherwise list every value.
constexpr std::size_t kMaxPerField = 3;

std::string item(const std::string& path, int index) { return path + '[' + std::to_string(index) + ']'; }

// `in_array`: snapshot_conversion.cpp's array checks name a non-finite
// value of a packed array by its item already.
void check_double(Problems& problems, const std::string& path, double value, bool in_array) {
  if (!std::isfinite(value)) {
    if (!in_array) problems.emplace_back(path, "is not a finite number (" + format_number(value) + ")");
  } else if (std::abs(value) > kLargestMagnitude) {
    problems.emplace_back(path, "is " + format_number(value) + ", beyond " + format_number(kLargestMagnitude) +
                                    " in magnitude, which the force arithmetic cannot carry");
  }
}

// Every double finite and within kLargestMagnitude, every enum a value its
// type names, in any message of the snapshot, through reflection so a field
// added to snapshot.proto is checked without a line here.
void check_values(Problems& problems, const Message& message, const std::string& prefix) {
  const auto* descriptor = message.GetDescriptor();
  const auto* reflection = message.GetReflection();
  for (int f = 0; f < descriptor->field_count(); ++f) {
    const FieldDescriptor* field = descriptor->field(f);
    const std::string path = prefix.empty() ? field->name() : prefix + '.' + field->name();
    if (field->is_repeated()) {
      const int size = reflection->FieldSize(message, field);
      std::size_t found = 0;
      for (int i = 0; i < size && found < kMaxPerField; ++i) {
        const std::size_t before = problems.size();
        switch (field->cpp_type()) {
          case FieldDescriptor::CPPTYPE_DOUBLE: {
            // The item's path only for a value that has a problem: a
            // 100,000-particle snapshot has millions of good ones.
            const double value = reflection->GetRepeatedDouble(message, field, i);
            if (!std::isfinite(value) || std::abs(value) > kLargestMagnitude) {
              check_double(problems, item(path, i), value, true);
            }
            break;
          }
          case FieldDescriptor::CPPTYPE_ENUM:
            if (field->enum_type()->FindValueByNumber(reflection->GetRepeatedEnumValue(message, field, i)) == nullptr) {
              problems.emplace_back(item(path, i), "is not a known value");
            }
            break;
          case FieldDescriptor::CPPTYPE_MESSAGE:
            check_values(problems, reflection->GetRepeatedMessage(message, field, i), item(path, i));
            break;
          default:
            break;
        }
        found += problems.size() - before;
      }
      continue;
    }
    switch (field->cpp_type()) {
      case FieldDescriptor::CPPTYPE_DOUBLE:
        check_double(problems, path, reflection->GetDouble(message, field), false);
        break;
      case FieldDescriptor::CPPTYPE_ENUM: {
        const int value = reflection->GetEnumValue(message, field);
        if (field->enum_type()->FindValueByNumber(value) == nullptr) {
          problems.emplace_back(path, "is " + std::to_string(value) + ", not a known " + field->enum_type()->name());
        }
        break;
      }
      case FieldDescriptor::CPPTYPE_MESSAGE:
        if (reflection->HasField(message, field)) {
          check_values(problems, reflection->GetMessage(message, field), path);
        }
        break;
      default:
        break;
    }
  }
}

// A quantity that is divided by or whose square root is taken (density,
// stiffness, radius, the step): 0 where allowed, else at least kSmallestMagnitude.
void check_not_tiny(Problems& problems, const std::string& path, double value) {
  if (value != 0 && std::abs(value) < kSmallestMagnitude) {
    problems.emplace_back(path, "is " + format_number(value) + ", below " + format_number(kSmallestMagnitude) +
                                    ", which underflows masses and time steps to 0");
  }
}

void check_names(Problems& problems, const proto::Snapshot& m) {
  std::map<std::string, int, std::less<>> walls;
  for (int i = 0; i < m.walls_size(); ++i) {
    if (const auto [first, inserted] = walls.emplace(m.walls(i).name(), i); !inserted) {
      problems.emplace_back(item("walls", i) + ".name", "duplicate wall name \"" + m.walls(i).name() + "\" (" +
                                                            item("walls", first->second) + " has it too)");
    }
  }
  std::map<std::string, int, std::less<>> materials;
  for (int i = 0; i < m.settings().materials_size(); ++i) {
    const std::string& name = m.settings().materials(i).name();
    if (const auto [first, inserted] = materials.emplace(name, i); !inserted) {
      problems.emplace_back(
          item("settings.materials", i) + ".name",
          "duplicate material name \"" + name + "\" (" + item("settings.materials", first->second) + " has it too)");
    }
  }
}

void check_counts(Problems& problems, const proto::Snapshot& m, const ResourceLimits& limits) {
  if (const auto problem = thread_count_problem(m.settings().threads(), limits)) {
    problems.emplace_back("settings.threads", *problem);
  }
  for (int i = 0; i < m.walls_size(); ++i) {
    if (m.walls(i).contacts() < 0) {
      problems.emplace_back(item("walls", i) + ".contacts",
                            "must be >= 0 (got " + std::to_string(m.walls(i).contacts()) + ")");
    }
  }
  if (const auto problem = particle_count_problem(static_cast<std::uint64_t>(m.particles().radius_size()), limits)) {
    // The message says "define N particles, ..." of a case; a snapshot holds them.
    problems.emplace_back("particles", "holds" + problem->substr(problem->find(' ')));
  }
}

void check_small_quantities(Problems& problems, const proto::Snapshot& m) {
  const proto::SnapshotSettings& s = m.settings();
  for (int i = 0; i < s.materials_size(); ++i) {
    const std::string path = item("settings.materials", i);
    check_not_tiny(problems, path + ".density", s.materials(i).density());
    check_not_tiny(problems, path + ".youngs_modulus", s.materials(i).youngs_modulus());
  }
  for (int i = 0; i < s.contact_models_size(); ++i) {
    const std::string path = item("settings.contact_models", i);
    check_not_tiny(problems, path + ".linear_normal_stiffness", s.contact_models(i).linear_normal_stiffness());
    check_not_tiny(problems, path + ".linear_shear_stiffness", s.contact_models(i).linear_shear_stiffness());
  }
  for (int i = 0; i < m.particles().radius_size() && problems.size() < kMaxPerField; ++i) {
    check_not_tiny(problems, item("particles.radius", i), m.particles().radius(i));
  }
  check_not_tiny(problems, "settings.fixed_time_step", s.fixed_time_step());
  check_not_tiny(problems, "time_step", m.time_step());
}

}  // namespace

std::vector<std::pair<std::string, std::string>> snapshot_value_problems(const proto::Snapshot& message,
                                                                         const ResourceLimits& limits) {
  Problems problems;
  check_values(problems, message, "");
  check_names(problems, message);
  check_counts(problems, message, limits);
  check_small_quantities(problems, message);
  return problems;
}

}  // namespace dem::io
