#include "dem/io/world_checks.h"

#include <cmath>
#include <string>

#include "format_number.h"

namespace dem::io {

namespace {

// A fixed step beyond the critical step, named by `path` (its .fixed).
void check_fixed_step(double step, double critical, const CaseSource& source, const std::string& path) {
  // A small tolerance: a case may write the critical step itself, rounded.
  if (std::isfinite(critical) && step > critical * (1.0 + 1e-9)) {
    throw CaseError(describe_problem(
        source, path + ".fixed",
        format_number(step) + " s exceeds the critical time step " + format_number(critical) +
            " s (2 sqrt(m/k) for linear laws, Rayleigh's for Hertz laws, times sqrt(1 + zeta^2) - zeta for the "
            "dashpots' damping ratio zeta), beyond which central differences are unstable and the run blows up; "
            "use at most " +
            format_number(critical) + " s, or a fraction instead"));
  }
}

}  // namespace

template <int Dim>
void check_built_world(const BasicWorld<Dim>& world, const CaseSource& source) {
  const double step = world.time_step();
  const double critical = world.critical_time_step();
  if (!(step > 0) || !std::isfinite(step)) {
    throw CaseError(describe_problem(source, "time_step",
                                     "the time step works out to " + format_number(step) +
                                         " s; the particles' masses and the contact stiffnesses give no finite "
                                         "critical step (" +
                                         format_number(critical) + " s)"));
  }
  check_fixed_step(step, critical, source, "time_step");
}

template <int Dim>
void check_built_world(const BasicWorld<Dim>& world, const std::vector<StageDefT<Dim>>& stages,
                       const CaseSource& source) {
  check_built_world(world, source);
  // What each stage keeps from the one before: the damping and a fixed step (0: a fraction).
  DampingDef damping = world.damping();
  double fixed = world.fixed_time_step();
  std::string fixed_by = "time_step";
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const std::string stage = "stage[" + std::to_string(i) + "]";
    if (stages[i].time_step) {
      fixed = stages[i].time_step->fixed;
      fixed_by = stage + ".time_step";
    }
    if (stages[i].damping) damping = *stages[i].damping;
    if (fixed > 0.0 && (stages[i].damping || stages[i].time_step)) {
      check_fixed_step(fixed, world.critical_time_step_with(damping), source,
                       stages[i].time_step ? fixed_by : stage + ".damping: with it, " + fixed_by);
    }
  }
}

template void check_built_world<2>(const BasicWorld<2>&, const CaseSource&);
template void check_built_world<3>(const BasicWorld<3>&, const CaseSource&);
template void check_built_world<2>(const BasicWorld<2>&, const std::vector<StageDefT<2>>&, const CaseSource&);
template void check_built_world<3>(const BasicWorld<3>&, const std::vector<StageDefT<3>>&, const CaseSource&);

}  // namespace dem::io
