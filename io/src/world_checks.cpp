#include "dem/io/world_checks.h"

#include <cmath>
#include <string>

#include "format_number.h"

namespace dem::io {

namespace {

// How a step was set: a fixed step (seconds) or a fraction (of the
// undamped critical step), and by which field.
struct StepSetting {
  double fixed = 0.0;
  double fraction = 0.0;
  std::string path = "time_step";
};

// A step beyond the critical step, named by the field that set it (its
// .fixed or .fraction); `because` says when a stage's damping moved it.
void check_step(const StepSetting& setting, double undamped, double critical, const CaseSource& source,
                const std::string& because = {}) {
  const bool fixed = setting.fixed > 0.0;
  const double step = fixed ? setting.fixed : setting.fraction * undamped;
  // A small tolerance: a case may write the critical step itself, rounded.
  if (!std::isfinite(critical) || step <= critical * (1.0 + 1e-9)) return;
  const std::string critical_text =
      "the critical time step " + format_number(critical) +
      " s (2 sqrt(m/k) for linear laws, Rayleigh's for Hertz laws, times sqrt(1 + zeta^2) - zeta for the "
      "dashpots' damping ratio zeta and 1 / sqrt(1 + alpha) for local damping), beyond which central differences "
      "are unstable and the run blows up";
  const std::string what =
      fixed ? format_number(step) + " s exceeds " + critical_text + "; use at most " + format_number(critical) + " s"
            : "gives " + format_number(step) + " s (of the undamped critical step " + format_number(undamped) +
                  " s), which exceeds " + critical_text + "; use at most " + format_number(critical / undamped);
  throw CaseError(describe_problem(source, setting.path + (fixed ? ".fixed" : ".fraction"), because + what));
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
  const double undamped = world.undamped_critical_time_step();
  check_step({world.fixed_time_step(), step / undamped}, undamped, critical, source);
}

template <int Dim>
void check_built_world(const BasicWorld<Dim>& world, const std::vector<StageDefT<Dim>>& stages,
                       const CaseSource& source) {
  check_built_world(world, source);
  // What each stage keeps from the one before: the damping and the step.
  const double undamped = world.undamped_critical_time_step();
  DampingDef damping = world.damping();
  StepSetting step{world.fixed_time_step(), world.time_step() / undamped};
  for (std::size_t i = 0; i < stages.size(); ++i) {
    const std::string stage = "stage[" + std::to_string(i) + "]";
    if (stages[i].time_step) step = {stages[i].time_step->fixed, stages[i].time_step->fraction, stage + ".time_step"};
    if (stages[i].damping) damping = *stages[i].damping;
    if (stages[i].damping || stages[i].time_step) {
      check_step(step, undamped, world.critical_time_step_with(damping), source,
                 stages[i].time_step ? std::string() : "with " + stage + ".damping, ");
    }
  }
}

template void check_built_world<2>(const BasicWorld<2>&, const CaseSource&);
template void check_built_world<3>(const BasicWorld<3>&, const CaseSource&);
template void check_built_world<2>(const BasicWorld<2>&, const std::vector<StageDefT<2>>&, const CaseSource&);
template void check_built_world<3>(const BasicWorld<3>&, const std::vector<StageDefT<3>>&, const CaseSource&);

}  // namespace dem::io
