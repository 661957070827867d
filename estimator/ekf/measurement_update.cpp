#include "estimator/ekf/measurement_update.hpp"

#include <cmath>
#include <Eigen/Cholesky>

#include "estimator/ekf/covariance.hpp"

namespace sinu::est {

UpdateResult fuse_measurement(StateMat& P, StateVec& dx, const Measurement& m) {
  const Eigen::Index n = P.rows();
  const Eigen::Index rows = m.innovation.rows();
  UpdateResult r;
  r.rows = rows;
  dx.setZero(n);

  using PHt_t = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxStates, kMaxMeasurementRows>;
  PHt_t PHt(n, rows);
  PHt.noalias() = P * m.H.transpose();
  MeasMat S(rows, rows);
  S.noalias() = m.H * PHt;
  S += m.R;
  S = 0.5 * (S + S.transpose()).eval();

  bool pass = true;
  for (Eigen::Index i = 0; i < rows; ++i) {
    r.innovation(i) = m.innovation(i);
    r.innovation_sigma(i) = std::sqrt(std::max(S(i, i), 0.0));
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
  dx.noalias() = KT.transpose() * m.innovation;

  StateMat A = StateMat::Identity(n, n);
  A.noalias() -= KT.transpose() * m.H;
  StateMat AP(n, n);
  AP.noalias() = A * P;
  PHt_t KR(n, rows);
  KR.noalias() = KT.transpose() * m.R;
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = i; j < n; ++j) P(i, j) = AP.row(i).dot(A.row(j)) + KR.row(i).dot(KT.col(j));
    if (!(P(i, i) > 0.0)) P(i, i) = 0.0;
  }
  mirror_upper(P);
  r.accepted = true;
  return r;
}

}  // namespace sinu::est
