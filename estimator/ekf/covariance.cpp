#include "estimator/ekf/covariance.hpp"

#include <array>

namespace sinu::est {

void mirror_upper(StateMat& P) {
  const Eigen::Index n = P.rows();
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = j + 1; i < n; ++i) P(i, j) = P(j, i);
  }
}

void propagate_covariance(StateMat& P, const StateMat& Phi, const StateVec& q_diag) {
  // Phi = I + F dt is sparse (nav rows, companion blocks, identity elsewhere):
  // gather each row's non-zeros once, then A = Phi P and the upper triangle of
  // A Phi^T cost nnz(Phi) * n instead of n^3.
  const Eigen::Index n = P.rows();
  // Only the first nnz[r] entries of each row are ever read: no need to clear
  // 50 KB per call.
  std::array<std::array<Eigen::Index, kMaxStates>, kMaxStates> col;
  std::array<std::array<double, kMaxStates>, kMaxStates> val;
  std::array<Eigen::Index, kMaxStates> nnz{};
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(i);
    for (Eigen::Index k = 0; k < n; ++k) {
      if (Phi(i, k) == 0.0) continue;
      const auto c = static_cast<std::size_t>(nnz[r]++);
      col[r][c] = k;
      val[r][c] = Phi(i, k);
    }
  }
  StateMat A(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(i);
    A.row(i).setZero();
    for (Eigen::Index c = 0; c < nnz[r]; ++c) {
      const auto cc = static_cast<std::size_t>(c);
      A.row(i) += val[r][cc] * P.col(col[r][cc]).transpose();  // P symmetric: contiguous column
    }
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto r = static_cast<std::size_t>(j);
    for (Eigen::Index i = 0; i <= j; ++i) {
      double sum = 0.0;
      for (Eigen::Index c = 0; c < nnz[r]; ++c) {
        const auto cc = static_cast<std::size_t>(c);
        sum += A(i, col[r][cc]) * val[r][cc];
      }
      P(i, j) = sum;
    }
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    P(i, i) += q_diag(i);
    if (!(P(i, i) > 0.0)) P(i, i) = 0.0;
  }
  mirror_upper(P);
}

}  // namespace sinu::est
