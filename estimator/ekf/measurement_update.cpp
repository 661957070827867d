#include "estimator/ekf/measurement_update.hpp"

#include <cmath>
#include <Eigen/Cholesky>

#include "estimator/ekf/covariance.hpp"

namespace sinu::est {

UpdateResult fuse_measurement(StateMat& P, StateVec& dx, const Measurement& m, const StateMask& frozen) {
  const Eigen::Index n = P.rows();
  const Eigen::Index rows = m.innovation.rows();
  UpdateResult r;
  r.rows = rows;
  dx.setZero(n);

  using PHt_t = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxStates, kMaxMeasurementRows>;
  // U = P H^T from H's non-zero entries only (a few per row: position, attitude,
  // the aiding source's own states): nnz(H) column axpys instead of n^2 m.
  PHt_t PHt = PHt_t::Zero(n, rows);
  for (Eigen::Index k = 0; k < n; ++k) {
    for (Eigen::Index row = 0; row < rows; ++row) {
      const double h = m.H(row, k);
      if (h != 0.0) PHt.col(row) += h * P.col(k);
    }
  }
  MeasMat S(rows, rows);
  S.noalias() = m.H * PHt;
  S += m.R;
  S = 0.5 * (S + S.transpose()).eval();

  bool pass = true;
  for (Eigen::Index i = 0; i < rows; ++i) {
    r.innovation(i) = m.innovation(i);
    r.innovation_sigma(i) = std::sqrt(std::max(S(i, i), 0.0));
    r.noise_sigma(i) = std::sqrt(std::max(m.R(i, i), 0.0));
    r.test_ratio(i) = m.innovation(i) * m.innovation(i) / (m.gate_sigma * m.gate_sigma * S(i, i));
    if (!std::isfinite(r.test_ratio(i)) || r.test_ratio(i) > 1.0) pass = false;
  }
  Eigen::LLT<MeasMat> llt(S);
  if (llt.info() != Eigen::Success) pass = false;
  if (pass) r.nis = m.innovation.dot(llt.solve(m.innovation));
  if (!pass || !std::isfinite(r.nis)) return r;

  // K = P H^T S^-1
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxMeasurementRows, kMaxStates> KT(rows, n);
  KT = llt.solve(PHt.transpose());
  if (frozen.any()) {
    for (Eigen::Index k = 0; k < n; ++k)
      if (frozen.test(static_cast<std::size_t>(k))) KT.col(k).setZero();
  }
  dx.noalias() = KT.transpose() * m.innovation;

  // Joseph form, expanded so it costs n^2 m instead of n^3 (same algebra for
  // any gain K, so it keeps its robustness to rounding in K):
  //   (I - K H) P (I - K H)^T + K R K^T = P - K U^T - U K^T + K S K^T,  U = P H^T.
  const auto K = KT.transpose();
  PHt_t KS_minus_U(n, rows);
  KS_minus_U.noalias() = K * S;
  KS_minus_U -= PHt;
  StateMat D(n, n);
  D.noalias() = KS_minus_U * KT;
  D.noalias() -= K * PHt.transpose();
  for (Eigen::Index j = 0; j < n; ++j) {
    for (Eigen::Index i = 0; i <= j; ++i) P(i, j) += D(i, j);
    if (!(P(j, j) > 0.0)) P(j, j) = 0.0;
  }
  mirror_upper(P);  // upper triangle computed: P stays exactly symmetric
  r.accepted = true;
  return r;
}

}  // namespace sinu::est
