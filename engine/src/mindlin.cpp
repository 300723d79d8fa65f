#include "mindlin.h"

#include <algorithm>
#include <cmath>

namespace dem {

namespace {

enum class Branch { kLoading, kUnloading, kReloading, kLagging };

// theta = (1 - x)^(1/3) with x kept in [0, 1]: x > 1 means full slip.
double cube_root_of_remainder(double x) { return std::cbrt(std::clamp(1.0 - x, 0.0, 1.0)); }

}  // namespace

double mindlin_step(MindlinHistory& h, double& T, double N, double dN, double a, double ds, double mu,
                    double shear_modulus) {
  if (h.direction == 0.0) {
    if (ds == 0.0) return 1.0;
    h.direction = ds > 0.0 ? 1.0 : -1.0;  // virgin loading: CDF follows the first displacement
  }
  const double cdf = h.direction;
  const double stiffness = 8.0 * shear_modulus * a;  // 8 G* a (Randall 3.52)
  const double friction_force = mu * N;
  const double forward = ds * cdf;
  const double T_old = T;

  // Reversals (4.3.1): moving back starts unloading from T*; moving forward
  // again after unloading starts reloading from T**. Only the first two
  // reversal points are stored; later ones inside them are non-linear
  // elastic on the reloading curve (Randall 3.3).
  if (forward < 0.0 && !h.unloading) {
    h.unloading = true;
    h.t_star = T_old;
  } else if (forward > 0.0 && h.unloading && !h.reloading) {
    h.reloading = true;
    h.t_star2 = T_old;
  }

  // THETA (4.3.2): which curve the step follows.
  Branch branch;
  if (forward > 0.0) {
    branch = h.unloading && T * cdf < h.t_star * cdf ? Branch::kReloading : Branch::kLoading;
    if (branch == Branch::kLoading) h.unloading = h.reloading = false;
  } else if (h.reloading && T * cdf > h.t_star2 * cdf) {
    branch = Branch::kReloading;  // re-unloading inside the reloading loop
  } else {
    branch = Branch::kUnloading;
  }
  // While N grows faster than the tangential load can follow, the slip
  // annulus does not advance: theta = 1 (3.98, 4.16, 4.25).
  const double critical_ds = dN != 0.0 && stiffness > 0.0 ? mu * dN / stiffness : 0.0;  // (4.16)
  if (dN > 0.0 && forward < critical_ds + h.lag) branch = Branch::kLagging;

  double theta = 1.0;
  if (friction_force > 0.0) {
    switch (branch) {
      case Branch::kLoading:  // (3.95, 4.22)
        theta = cube_root_of_remainder((T * cdf + mu * dN) / friction_force);
        break;
      case Branch::kUnloading:  // (3.96, 4.23)
        theta = cube_root_of_remainder((h.t_star * cdf - T * cdf + 2.0 * mu * dN) / (2.0 * friction_force));
        break;
      case Branch::kReloading:  // (3.97, 4.24), measured from T** where reloading began
        theta = cube_root_of_remainder((T * cdf - h.t_star2 * cdf + 2.0 * mu * dN) / (2.0 * friction_force));
        break;
      case Branch::kLagging:  // (3.98, 4.25)
        theta = 1.0;
        break;
    }
  }
  // (4.15): the sign of the mu dN term is negative for unloading only.
  const double unloading_flag = branch == Branch::kUnloading ? -1.0 : 1.0;
  const double increment = cdf * (theta * (stiffness * ds * cdf - mu * dN * unloading_flag) + mu * dN * unloading_flag);
  T += increment;

  // DD (4.17-4.18): how far the contact lags behind its constant-N curve.
  if (dN > 0.0) {
    if (increment * cdf < mu * dN || h.lag > 0.0) h.lag = std::max(0.0, h.lag + critical_ds - forward);
  } else if (dN < 0.0) {
    h.lag = std::max(0.0, h.lag + critical_ds);
  }
  // A changing N moves the stored reversal points with it (4.20-4.21).
  if (h.unloading) h.t_star += cdf * mu * dN;
  if (h.reloading) h.t_star2 -= cdf * mu * dN;

  // Erased history (4.3.1, end): reloading that passes T* resumes virgin
  // loading; re-unloading that passes T** is back on the unloading curve;
  // unloading that passes -T* has wiped the old slip and loads virgin the
  // other way.
  if (h.reloading && T * cdf >= h.t_star * cdf) {
    h.unloading = h.reloading = false;
  } else if (h.reloading && branch == Branch::kReloading && forward < 0.0 && T * cdf <= h.t_star2 * cdf) {
    h.reloading = false;
  } else if (h.unloading && !h.reloading && T * cdf <= -h.t_star * cdf) {
    h.direction = -cdf;
    h.unloading = h.reloading = false;
  }
  return theta;
}

void mindlin_slide(MindlinHistory& h, double T) {
  h.direction = T >= 0.0 ? 1.0 : -1.0;
  h.unloading = h.reloading = false;
  h.t_star = h.t_star2 = 0.0;
  h.lag = 0.0;
}

}  // namespace dem
