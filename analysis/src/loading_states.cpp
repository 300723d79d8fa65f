#include "dem/analysis/loading_states.h"

#include <algorithm>
#include <vector>

namespace dem::analysis {
namespace {

// Least-squares line y = c + m x: the slope m and R^2.
struct Line {
  double slope = 0.0;
  double r_squared = 0.0;
};

Line fit_line(const std::vector<double>& x, const std::vector<double>& y) {
  const auto n = static_cast<double>(x.size());
  if (x.size() < 2) return {};
  double mx = 0.0, my = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += x[i];
    my += y[i];
  }
  mx /= n;
  my /= n;
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    sxx += (x[i] - mx) * (x[i] - mx);
    sxy += (x[i] - mx) * (y[i] - my);
    syy += (y[i] - my) * (y[i] - my);
  }
  if (!(sxx > 0.0)) return {};
  Line line;
  line.slope = sxy / sxx;
  line.r_squared = syy > 0.0 ? sxy * sxy / (sxx * syy) : 1.0;
  return line;
}

}  // namespace

std::string_view state_name(LoadingState state) {
  switch (state) {
    case LoadingState::kInitial:
      return "initial";
    case LoadingState::kTransition:
      return "transition";
    case LoadingState::kFinal:
      return "final";
  }
  return "initial";
}

StateCycles state_cycles(std::span<const CompressionSample> samples, double transition_stress, double final_stress) {
  StateCycles cycles;
  for (const CompressionSample& s : samples) {
    if (!cycles.transition && s.stress >= transition_stress) cycles.transition = s.cycle;
    if (!cycles.final && s.stress >= final_stress) cycles.final = s.cycle;
  }
  return cycles;
}

LoadingState state_at(std::uint64_t cycle, const StateCycles& cycles) {
  if (cycles.final && cycle >= *cycles.final) return LoadingState::kFinal;
  if (cycles.transition && cycle >= *cycles.transition) return LoadingState::kTransition;
  return LoadingState::kInitial;
}

std::array<StateFit, 3> fit_states(std::span<const CompressionSample> samples, const StateCycles& cycles) {
  std::array<StateFit, 3> fits;
  std::array<std::vector<double>, 3> settlement, stress, contacts;
  const auto touched =
      std::find_if(samples.begin(), samples.end(), [](const CompressionSample& s) { return s.loading_contacts > 0; });
  for (auto it = touched; it != samples.end(); ++it) {
    const auto k = static_cast<std::size_t>(state_at(it->cycle, cycles));
    StateFit& fit = fits[k];
    if (fit.samples == 0) {
      fit.first_cycle = it->cycle;
      fit.stress_from = it->stress;
      fit.settlement_from = it->settlement;
      fit.loading_contacts_from = it->loading_contacts;
    }
    fit.samples += 1;
    fit.stress_to = it->stress;
    fit.settlement_to = it->settlement;
    fit.loading_contacts_to = it->loading_contacts;
    settlement[k].push_back(it->settlement);
    stress[k].push_back(it->stress);
    contacts[k].push_back(it->loading_contacts);
  }
  for (std::size_t k = 0; k < fits.size(); ++k) {
    fits[k].state = kLoadingStates[k];
    const double settled = fits[k].settlement_to - fits[k].settlement_from;
    if (settled > 0.0) fits[k].secant_stiffness = (fits[k].stress_to - fits[k].stress_from) / settled;
    const Line curve = fit_line(settlement[k], stress[k]);
    fits[k].tangent_stiffness = curve.slope;
    fits[k].r_squared = curve.r_squared;
    fits[k].contact_rate = fit_line(stress[k], contacts[k]).slope;
  }
  return fits;
}

}  // namespace dem::analysis
