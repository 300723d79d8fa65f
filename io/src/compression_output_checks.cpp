#include "compression_output_checks.h"

#include <string>

#include "case_fields.h"
#include "dem/analysis/compression_settings.h"
#include "field_path.h"
#include "format_number.h"

namespace dem::io {
namespace {

constexpr const char* kPath = "output.compression";

// Its numbers passed their rules (case_rules.h); these hold across them.
void check_force_distribution(const proto::ForceDistributionOutput& d, ProblemList& problems) {
  const std::string path = std::string(kPath) + ".force_distribution";
  if (!problems.reported(path + ".stress_to") && !problems.reported(path + ".stress_from") &&
      !(d.stress_to() > d.stress_from())) {
    problems.add(path + ".stress_to", "must exceed stress_from (" + format_number(d.stress_to()) +
                                          " <= " + format_number(d.stress_from()) + ")");
  }
  if (d.snapshots() == 1) {
    problems.add(path + ".snapshots",
                 "must be at least 2 (the first at stress_from, the last at stress_to); "
                 "leave it out for 10");
  }
}

}  // namespace

void check_compression_output(const proto::CompressionOutput& c, const NameIndex& walls, ProblemList& problems) {
  const std::string path = kPath;
  const int loading = find_wall(problems, walls, path + ".loading_plate", c.loading_plate());
  const int bottom = find_wall(problems, walls, path + ".bottom_plate", c.bottom_plate());
  if (loading >= 0 && loading == bottom) {
    problems.add(path + ".bottom_plate",
                 "must differ from loading_plate (both are " + in_quotes(c.bottom_plate()) + ")");
  }
  check_fields<analysis::CompressionSettings>(c, path, problems);  // each number by its rule (case_rules.h)
  const bool transition_ok = !problems.reported(path + ".transition_stress");
  const bool final_ok = !problems.reported(path + ".final_stress");
  const analysis::CompressionSettings defaults;
  const double transition = c.transition_stress() > 0 ? c.transition_stress() : defaults.transition_stress;
  const double final_stress = c.final_stress() > 0 ? c.final_stress() : defaults.final_stress;
  if (transition_ok && final_ok && !(final_stress > transition)) {
    problems.add(path + ".final_stress", "must exceed transition_stress (" + format_number(final_stress) +
                                             " <= " + format_number(transition) + "; 0 stands for the defaults, " +
                                             format_number(defaults.transition_stress) + " and " +
                                             format_number(defaults.final_stress) + ")");
  }
  if (c.has_force_distribution()) check_force_distribution(c.force_distribution(), problems);
  if (!problems.reported(path + ".stress_drop_fraction") && !(c.stress_drop_fraction() < 1)) {
    problems.add(path + ".stress_drop_fraction", "must be in [0, 1) (got " + format_number(c.stress_drop_fraction()) +
                                                     "); leave it out for " +
                                                     format_number(defaults.stress_drop_fraction));
  }
}

}  // namespace dem::io
