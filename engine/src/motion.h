// The law of motion (Cundall & Strack eqs. 20-23a, with global damping eqs.
// 29-36 and the body force term), applied to the force sums of the last
// force pass.
#pragma once

#include "contact_blocks.h"
#include "dem/definitions.h"
#include "particles.h"
#include "periodic.h"

namespace dem {

// What one integration step reports.
struct MotionStep {
  double max_travel = 0.0;       // largest distance from the positions at the last contact-table rebuild
  double max_speed = 0.0;        // largest particle speed over the step
  double gravity_work = 0.0;     // J (energy budget only)
  double global_damping = 0.0;   // J dissipated (energy budget only)
  double local_damping = 0.0;    // J dissipated (energy budget only)
  double continuum_work = 0.0;   // J done by a box's continuum field (energy budget only)
  double time_step_ratio = 0.0;  // dt over the smallest particle-wise critical step (Randall 4.35-4.40)
};

// What one integration step is asked for.
template <int Dim>
struct MotionInputs {
  const Periodic<Dim>& periodic;
  Vec<Dim> gravity;
  const DampingDef& damping;
  double dt;
  int threads;
  bool energy_budget;  // book gravity's work and the damping's losses
  bool keep_force;     // remember each |sum F| for the next step's check
  bool check_step;     // Randall's particle-wise check against the kept |sum F|
  // The force pass's side-by-side copies (contact_blocks.h) to write as the
  // particles move, or null: each particle's new values are still in the
  // core's cache here, where the pass would read them back from memory.
  HotPlace<Dim>* hot_place = nullptr;
  HotMotion<Dim>* hot_motion = nullptr;
  // Randall's centripetal gravity field (6.4.2), or null.
  const CentripetalGravityT<Dim>* centripetal = nullptr;
  // A box's continuum field (Randall 4.5.2): the one the velocities carry
  // from the last step, and this step's; null when none.
  const ContinuumFieldT<Dim>* continuum_before = nullptr;
  const ContinuumFieldT<Dim>* continuum = nullptr;
};

// Time-centred central differences (Cundall & Strack eqs. 35-36, then
// 22a-23a) with the body forces, global damping (eq. 34; Miyata eq. 32) and
// local non-viscous damping (Miyata eq. 33). Positions that leave a
// periodic cell enter it on the other side. Ellipsoids turn by Euler's
// equations with their inertia tensor. Under a continuum field (Randall
// 4.5.2) a particle's velocity is its own, integrated and damped as above,
// plus the field's at its place (eqs. 4.43-4.44), and it moves with both
// (eq. 4.41).
template <int Dim>
MotionStep integrate_motion(Particles<Dim>& particles, const MotionInputs<Dim>& inputs);

}  // namespace dem
