#include "estimator/align/field_heading_update.hpp"

#include <cmath>

#include "estimator/ins/rotation.hpp"

namespace sinu::est {
namespace {
constexpr int kIterations = 6;
constexpr double kMinHorizontalFraction = 0.05;  // below: the field's heading is noise (within ~3 deg of a pole)
constexpr double kGate = 9.0;                    // innovation^2 / its variance: 3 sigma

struct Heading {
  double h_rad;            // horizontal angle of the field minus the declination, wrapped
  Eigen::RowVector3d J;    // dh/dphi
};

Heading heading_of(const Eigen::Quaterniond& q_nb, const Eigen::Vector3d& mag_b_uT, double declination_rad) {
  const Eigen::Vector3d m = q_nb * mag_b_uT;
  const double h2 = m.head<2>().squaredNorm();
  return {wrap_pi(std::atan2(m.y(), m.x()) - declination_rad),
          Eigen::RowVector3d(-m.z() * m.x() / h2, -m.z() * m.y() / h2, 1.0)};
}
}  // namespace

bool update_with_field_heading(Eigen::Quaterniond& q_nb, Eigen::Matrix3d& P_rad2, const Eigen::Vector3d& mag_b_uT,
                               double declination_rad, double heading_sigma_rad) {
  const Eigen::Vector3d m0 = q_nb * mag_b_uT;
  if (!mag_b_uT.allFinite() || !P_rad2.allFinite() || m0.head<2>().norm() < kMinHorizontalFraction * m0.norm())
    return false;
  const double R = heading_sigma_rad * heading_sigma_rad;
  const Heading first = heading_of(q_nb, mag_b_uT, declination_rad);
  if (first.h_rad * first.h_rad > kGate * ((first.J * P_rad2 * first.J.transpose())(0, 0) + R)) return false;
  // Iterated update: phi_{i+1} = K_i (J_i phi_i - h(phi_i)), K_i = P J_i^T / (J_i P J_i^T + R).
  Eigen::Vector3d phi = Eigen::Vector3d::Zero();
  Eigen::Vector3d K = Eigen::Vector3d::Zero();
  Eigen::RowVector3d J = first.J;
  for (int i = 0; i < kIterations; ++i) {
    const Heading now = heading_of(quat_from_rotation_vector(phi) * q_nb, mag_b_uT, declination_rad);
    J = now.J;
    K = P_rad2 * J.transpose() / ((J * P_rad2 * J.transpose())(0, 0) + R);
    phi = K * (J.dot(phi) - now.h_rad);
  }
  // C_true = (I + [phi x]) C_hat: the estimate moves by +phi.
  q_nb = (quat_from_rotation_vector(phi) * q_nb).normalized();
  const Eigen::Matrix3d P = (Eigen::Matrix3d::Identity() - K * J) * P_rad2;
  P_rad2 = 0.5 * (P + P.transpose());
  return true;
}

}  // namespace sinu::est
