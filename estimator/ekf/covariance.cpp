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
  // gather each row's non-zeros once, then
  //   B = P Phi^T   column by column: B(:, i) = sum_k Phi(i, k) P(:, k)
  //   P' = Phi B    upper triangle:   P'(i, j) = sum_k Phi(i, k) B(k, j)
  // cost nnz(Phi) * n each instead of n^3; every access is down a column.
  // Only the first nnz[r] entries of each row are ever read: no need to clear.
  const Eigen::Index n = P.rows();
  std::array<std::array<Eigen::Index, kMaxStates>, kMaxStates> col;
  std::array<std::array<double, kMaxStates>, kMaxStates> val;
  std::array<Eigen::Index, kMaxStates> nnz{};
  for (Eigen::Index k = 0; k < n; ++k) {  // down the columns of Phi (its storage order)
    for (Eigen::Index i = 0; i < n; ++i) {
      const double v = Phi(i, k);
      if (v == 0.0) continue;
      const auto r = static_cast<std::size_t>(i);
      const auto c = static_cast<std::size_t>(nnz[r]++);
      col[r][c] = k;
      val[r][c] = v;
    }
  }
  StateMat B(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto r = static_cast<std::size_t>(i);
    B.col(i) = val[r][0] * P.col(col[r][0]);
    for (Eigen::Index c = 1; c < nnz[r]; ++c) {
      const auto cc = static_cast<std::size_t>(c);
      B.col(i) += val[r][cc] * P.col(col[r][cc]);
    }
  }
  for (Eigen::Index j = 0; j < n; ++j) {
    const double* b = B.col(j).data();
    for (Eigen::Index i = 0; i <= j; ++i) {
      const auto r = static_cast<std::size_t>(i);
      double sum = 0.0;
      for (Eigen::Index c = 0; c < nnz[r]; ++c) {
        const auto cc = static_cast<std::size_t>(c);
        sum += val[r][cc] * b[col[r][cc]];
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
