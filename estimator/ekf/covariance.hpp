#pragma once
// Covariance propagation and the Joseph-form update, both computing one
// triangle and mirroring it so P stays exactly symmetric (as PX4 EKF2 does).
#include "estimator/ekf/state_layout.hpp"

namespace sinu::est {

/// P <- Phi P Phi^T + Q (Q diagonal, given as a vector). Upper triangle
/// computed, lower mirrored; variances floored at zero.
void propagate_covariance(StateMat& P, const StateMat& Phi, const StateVec& q_diag);

/// Copies the upper triangle into the lower one.
void mirror_upper(StateMat& P);

}  // namespace sinu::est
