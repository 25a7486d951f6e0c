#pragma once
// The explicit integrator's stable time step. Symplectic Euler on an
// oscillator of angular frequency w is stable for dt <= 2 / w (the implicit
// damping of explicit_integrator.h only widens this), so the limit is
// 2 / w_max with w_max^2 bounded by the block Gershgorin bound on
// M^(-1/2) K M^(-1/2):
//   w_max^2 <= max_i sum_j ||K_ij|| / sqrt(m_i m_j),
// each spring adding k to ||K_ii|| and ||K_ij|| (its Hessian's norm is k
// while it is not compressed below half its rest length; the geometric
// part (T/L)(I - n n^T) is smaller than k then), each bending term
// k_b |c_i c_j| with c = (1, -2, 1), each cell's twist term (when the sheet
// has them) k_t w over its four corners. Every spring of an untorn sheet is
// counted, so the bound holds whatever tears later. It is conservative: the
// test compares it with the exact w_max of small sheets. With the springs'
// dashpots (SheetSpec::stiffness_damping_s = beta, the damping ratio of mode
// w then z = beta w / 2, its damping force taken at v_n) the step is
// stable for (w dt)^2 + 4 z w dt <= 4, so the limit is
// (2 / w_max) (sqrt(1 + z^2) - z) with z = beta w_max / 2 (z >= 0 only
// shrinks it: the fastest mode has the largest z).

#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_params.h"

namespace repose {

// 2 / w_max (s), w_max from the bound above.
double stable_time_step_s(const SheetModel& model, const SheetParams& params);

}  // namespace repose
