// The Mindlin-Deresiewicz tangential law with its loading history, as
// Randall (1989) codes it in BALL's FORD and THETA (4.3.1-4.3.2): the
// general solution (3.94)
//   dT = 8 G* a theta ds +- mu dN (1 - theta)
// with theta from the loading case (3.95-3.98, coded as 4.22-4.25), the
// loading direction CDF, the first two reversal points T* and T** and the
// lag DD behind the constant-normal-force curve while N grows (4.16-4.18).
// T and ds are signed along one tangential axis.
#pragma once

#include "dem/snapshot.h"  // MindlinHistory

namespace dem {

// Advances the tangential force T over one step in which the normal force
// went to N (by dN), the contact radius is a and the tangential
// displacement increment is ds. Returns theta (the stiffness factor of the
// step). The caller applies the Coulomb limit and calls mindlin_slide when
// the contact slides.
double mindlin_step(MindlinHistory& h, double& T, double N, double dN, double a, double ds, double mu,
                    double shear_modulus);

// Rigid-body sliding erases the history: loading resumes from |T| = mu N in
// the sliding direction.
void mindlin_slide(MindlinHistory& h, double T);

}  // namespace dem
