#include "dem/analysis/force_distribution.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace dem::analysis {

double q_model_density(double f, int neighbours) {
  if (f < 0.0) return 0.0;
  const double n = neighbours;
  // Miyata eq. 62 in logarithms: N^N / (N-1)! overflows long before f^(N-1) e^(-Nf) underflows.
  return std::exp(n * std::log(n) - std::lgamma(n) + (n - 1.0) * std::log(f) - n * f);
}

double mueth_density(double f, const MuethFit& fit) {
  if (f < 0.0) return 0.0;
  return fit.a * (1.0 - fit.b * std::exp(-f * f)) * std::exp(-fit.beta * f);  // Miyata eq. 61
}

std::vector<double> normalised_forces(std::span<const double> forces) {
  const double sum = std::accumulate(forces.begin(), forces.end(), 0.0);
  if (forces.empty() || !(sum > 0.0)) return {};
  const double mean = sum / static_cast<double>(forces.size());
  std::vector<double> f;
  f.reserve(forces.size());
  for (double force : forces) f.push_back(force / mean);
  return f;
}

std::vector<ForceClass> force_classes(std::span<const double> f, double bin_width) {
  if (f.empty() || !(bin_width > 0.0)) return {};
  const double largest = *std::max_element(f.begin(), f.end());
  const auto count = static_cast<std::size_t>(std::floor(std::max(largest, 0.0) / bin_width)) + 1;
  std::vector<ForceClass> classes(count);
  for (std::size_t k = 0; k < count; ++k) {
    classes[k].f_low = static_cast<double>(k) * bin_width;
    classes[k].f_high = static_cast<double>(k + 1) * bin_width;
  }
  double total = 0.0;
  for (double value : f) {
    const auto k = std::min(static_cast<std::size_t>(std::floor(std::max(value, 0.0) / bin_width)), count - 1);
    classes[k].contacts += 1;
    classes[k].load_share += value;
    total += value;
  }
  const double n = static_cast<double>(f.size());
  for (ForceClass& c : classes) {
    c.probability_density = c.contacts / (n * bin_width);
    c.load_share = total > 0.0 ? c.load_share / total : 0.0;
  }
  return classes;
}

TailFit fit_exponential_tail(std::span<const double> f, double from) {
  TailFit fit;
  fit.from = from;
  double excess = 0.0;
  for (double value : f) {
    if (value > from) {
      excess += value - from;
      fit.contacts += 1;
    }
  }
  if (fit.contacts == 0 || !(excess > 0.0)) return fit;
  fit.decay_rate = fit.contacts / excess;
  fit.decay_rate_error = fit.decay_rate / std::sqrt(static_cast<double>(fit.contacts));
  if (fit.contacts < 2) return fit;
  const double mean = excess / fit.contacts;
  double squares = 0.0;
  for (double value : f) {
    if (value > from) squares += (value - from - mean) * (value - from - mean);
  }
  fit.excess_cv = std::sqrt(squares / (fit.contacts - 1)) / mean;
  return fit;
}

double tail_decay_rate(const std::function<double(double)>& density, double from) {
  // Simpson's rule over [from, from + 60]: the seed's densities decay at
  // rates of 1.5 and more, so what lies beyond is below 1e-39 of the mass.
  constexpr int kIntervals = 24000;
  constexpr double kLength = 60.0;
  const double h = kLength / kIntervals;
  double mass = 0.0, moment = 0.0;
  for (int k = 0; k <= kIntervals; ++k) {
    const double weight = (k == 0 || k == kIntervals) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    const double excess = k * h;
    const double p = density(from + excess);
    mass += weight * p;
    moment += weight * excess * p;
  }
  return moment > 0.0 ? mass / moment : 0.0;
}

}  // namespace dem::analysis
