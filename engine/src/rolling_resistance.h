// Rolling resistance (Iwashita & Oda 1998; Ai, Chen, Rotter & Ooi 2011,
// their model C): an elastic-plastic spring on the relative rotation of the
// bodies in contact, with a dashpot while it holds. An option of every
// contact law (ContactModelDef::rolling), run as its own pass after the
// force pass, over the touching rows, so a world without it pays one test
// per cycle and nothing else.
//
//   k_r = 2.25 k_n mu_r^2 R_r^2          the rolling stiffness Ai et al. choose
//   M_r <- M_r - k_r dtheta_r            dtheta_r = (omega_1 - omega_2) dt, in 3D the
//                                        part in the tangent plane (twisting is free)
//   |M_r| <= M_max = mu_r R_r F_n        the plastic limit
//   M_d = -eta_r 2 (I_r k_r)^(1/2) dtheta_r / dt   while |M_r| < M_max, and
//                                        |M_r + M_d| <= M_max (our choice: the
//                                        whole resistance keeps to the cap)
//
// with R_r = R_1 R_2 / (R_1 + R_2) (a wall: the particle's radius), k_n
// the law's normal stiffness (linear laws) or its current tangent stiffness
// 2 E* a (Hertz laws, Randall 3.15), and I_r = 1 / (1/(I_1 + m_1 R_1^2) +
// 1/(I_2 + m_2 R_2^2)). The first body receives M_r + M_d, the second
// minus that.
#pragma once

namespace dem {

template <int Dim>
struct WorldState;

// Whether any pair of materials has rolling resistance (mu_r > 0): the
// world then keeps the rolling column and runs the pass.
template <int Dim>
bool needs_rolling_resistance(const WorldState<Dim>& state);

// After the force pass: advances every touching row's rolling torque over
// the step and adds the torques to the particles' moment sums. Books the
// work done on the rolling springs with the tangential springs' (the
// energy budget's friction term then holds the rolling dissipation).
template <int Dim>
void apply_rolling_resistance(WorldState<Dim>& state);

// After an edit re-evaluated the force sums: adds the rolling springs'
// torques as they stand.
template <int Dim>
void add_rolling_moments(WorldState<Dim>& state);

}  // namespace dem
