// The distribution of the normalised contact force f = F/<F> on a plate
// (Miyata et al. 2002, 3.3(2), Figs. 35 and 37): its probability density
// and the share of the load each class of f carries, the two densities the
// seed compares it with, and the decay rate of its exponential tail. Plain
// numbers in, plain numbers out, so the service can publish them too.
#pragma once

#include <functional>
#include <span>
#include <vector>

namespace dem::analysis {

// Miyata eq. 62, the q-model (Liu et al. 1995, Coppersmith et al. 1996):
// P(f) = N^N / (N-1)! f^(N-1) exp(-N f), N the number of neighbours below
// each site of the lattice (the seed uses N = 3).
double q_model_density(double f, int neighbours);

// Miyata eq. 61, Mueth et al.'s (1998) fit to glass beads:
// P(f) = a (1 - b exp(-f^2)) exp(-beta f).
struct MuethFit {
  double a = 3.0;
  double b = 0.75;
  double beta = 1.5;
};
double mueth_density(double f, const MuethFit& fit = {});

// Each force over their mean (the seed's f, per plate and snapshot); empty
// when the forces are empty or sum to zero.
std::vector<double> normalised_forces(std::span<const double> forces);

// One class of f, [f_low, f_high).
struct ForceClass {
  double f_low = 0.0;
  double f_high = 0.0;
  int contacts = 0;
  double probability_density = 0.0;  // contacts / (all contacts x width) (Fig. 35)
  double load_share = 0.0;           // the sum of f in the class over the sum of all f (Fig. 37)
};

// Classes of width bin_width from 0 up to the largest f.
std::vector<ForceClass> force_classes(std::span<const double> f, double bin_width);

// P(f) ~ exp(-beta f) above f0: then f - f0 is exponential with rate beta,
// whose maximum-likelihood estimate is 1 / mean(f - f0), with standard
// error beta / sqrt(n). Not a fit to the histogram, so it does not depend
// on the classes' width.
// Whether the tail is exponential at all: the excesses f - f0 of an
// exponential tail have a coefficient of variation (standard deviation
// over mean) of 1; a tail cut off at some largest force has less (a
// uniform one 1/sqrt(3) = 0.58).
struct TailFit {
  double from = 1.0;
  int contacts = 0;         // the forces above `from`
  double decay_rate = 0.0;  // beta; 0 with no force above `from`
  double decay_rate_error = 0.0;
  double excess_cv = 0.0;  // 0 with fewer than two forces above `from`
};
TailFit fit_exponential_tail(std::span<const double> f, double from);

// The same estimator applied to a density: 1 / E[f - f0 | f > f0], by
// quadrature. For eqs. 61 and 62 it gives the rate the simulated tails are
// compared with.
double tail_decay_rate(const std::function<double(double)>& density, double from);

}  // namespace dem::analysis
