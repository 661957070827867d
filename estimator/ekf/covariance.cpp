#include "estimator/ekf/covariance.hpp"

namespace sinu::est {

void mirror_upper(StateMat& P) {
  const Eigen::Index n = P.rows();
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = j + 1; i < n; ++i) P(i, j) = P(j, i);
  }
}

void propagate_covariance(StateMat& P, const StateMat& Phi, const StateVec& q_diag) {
  const Eigen::Index n = P.rows();
  StateMat A(n, n);
  A.noalias() = Phi * P;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i; j < n; ++j) P(i, j) = A.row(i).dot(Phi.row(j));
    P(i, i) += q_diag(i);
    if (!(P(i, i) > 0.0)) P(i, i) = 0.0;
  }
  mirror_upper(P);
}

}  // namespace sinu::est
