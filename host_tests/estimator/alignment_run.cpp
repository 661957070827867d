#include "host_tests/estimator/alignment_run.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::test {

Trajectory make_flight(const Eigen::Vector3d& lever_b_m) {
  Trajectory r;
  r.truth = AnalyticFlight(FlightProfile{}).sample(kImuHz, 660.0);
  r.gnss = AnalyticFlight::gnss(r.truth, kGnssEvery, 0.0, lever_b_m, 0.5, 0.1);
  return r;
}
const Trajectory& flight() {
  static const Trajectory t = make_flight(Eigen::Vector3d::Zero());
  return t;
}

/// Straight, level flight at constant NED velocity (40 m/s, course 34 deg):
/// f_n = -g + (2 w_ie + w_en) x v, w_ib = C_bn (w_ie + w_en), constant Euler angles.
Trajectory straight_level(double duration_s, double accel_m_s2) {
  namespace w = est::wgs84;
  Trajectory r;
  const Eigen::Vector3d track(std::cos(0.6), std::sin(0.6), 0.0);
  const Eigen::Quaterniond q_nb = est::quat_from_euler(0.02, 0.05, 0.6);
  const Eigen::Matrix3d C_bn = q_nb.toRotationMatrix().transpose();
  double lat = 40.0 * kDeg, lon = -105.0 * kDeg;
  const double h = 1500.0, dt = 1.0 / kImuHz;
  const auto n = static_cast<std::size_t>(std::lround(duration_s * kImuHz));
  for (std::size_t i = 0; i <= n; ++i) {
    TruthSample s;
    s.nav.t_s = kFlightStart + static_cast<double>(i) * dt;
    const Eigen::Vector3d v_n = (40.0 + accel_m_s2 * static_cast<double>(i) * dt) * track;
    s.nav.q_nb = q_nb;
    s.nav.v_n_m_s = v_n;
    s.nav.lat_rad = lat;
    s.nav.lon_rad = lon;
    s.nav.h_m = h;
    const Eigen::Vector3d w_ie = w::omega_ie_n(lat), w_en = w::omega_en_n(lat, h, v_n);
    const Eigen::Vector3d g(0.0, 0.0, w::normal_gravity_m_s2(lat, h));
    s.imu.t_s = s.nav.t_s;
    s.imu.specific_force_b_m_s2 = C_bn * (accel_m_s2 * track - g + (2.0 * w_ie + w_en).cross(v_n));
    s.imu.angular_rate_b_rad_s = C_bn * (w_ie + w_en);
    r.truth.push_back(s);
    const Eigen::Vector3d v_mid = v_n + 0.5 * accel_m_s2 * dt * track;  // exact for a constant acceleration
    lat += v_mid.x() * dt / (w::meridian_radius_m(lat) + h);
    lon += v_mid.y() * dt / ((w::transverse_radius_m(lat) + h) * std::cos(lat));
  }
  r.gnss = AnalyticFlight::gnss(r.truth, kGnssEvery, 0.0, Eigen::Vector3d::Zero(), 0.5, 0.1);
  return r;
}

Errors realistic(unsigned seed) { return Errors{0.1, 1.0, 0.2 * kDeg, 0.05, 2.6e-3, 2.3e-2, seed}; }

est::InMotionAlignmentConfig matched(const Errors& e) {
  est::InMotionAlignmentConfig c;
  c.gnss_velocity_sigma_m_s = e.gnss_vel_sigma_m_s;
  c.gnss_velocity_corr_s = 0.0;  // the test's velocity noise is white
  c.gnss_height_sigma_m = e.gnss_h_sigma_m;
  c.gyro_bias_sigma_rad_s = e.gyro_bias_rad_s;
  c.accel_bias_sigma_m_s2 = e.accel_bias_m_s2;
  c.gyro_arw_rad_rt_s = e.gyro_white_rad_s / std::sqrt(kImuHz);
  return c;
}

est::InMotionAlignmentConfig calibrated() {
  est::InMotionAlignmentConfig c = matched(Errors{0.1, 1.0, 0.02 * kDeg, 0.02, 0.0, 0.0, 1});
  c.gyro_arw_rad_rt_s = 2.6e-4;
  return c;
}

/// Attitude error phi in NED with C_hat = (I - [phi x]) C_true (the EKF's
/// att state), split so that a large yaw error does not leak into the tilt:
/// north/east from the body's down axis, C (d_hat_b - d_b) = phi x e_down,
/// down from the Euler yaws (yaw_hat = yaw - phi_down).
Eigen::Vector3d attitude_error_ned(const Eigen::Quaterniond& est_q, const Eigen::Quaterniond& true_q) {
  const Eigen::Matrix3d C = true_q.toRotationMatrix();
  const Eigen::Vector3d down = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d d = C * (est_q.conjugate() * down - true_q.conjugate() * down);
  const double yaw_err = est::wrap_pi(est::euler_from_quat(est_q).z() - est::euler_from_quat(true_q).z());
  return {-d.y(), d.x(), -yaw_err};
}

/// Feeds [t_start, t_start + duration) of the trajectory (IMU and GNSS with
/// `err`, less `gaps`) into a fresh alignment and scores every solution.
/// Tilt ratios per axis once yaw is known; before, the magnitude against the
/// RSS sigma (the sigmas' axes turn with the unknown yaw). All ratios only
/// in the linear range (tilt sigma < 3 deg): early in a steady turn or
/// speed change the weak axis is the tilted specific force, and errors of
/// tens of degrees are first-order sigmas no more.
Outcome run(const Trajectory& tr, double t_start_s, double duration_s, const est::InMotionAlignmentConfig& cfg,
            const Errors& err, const Gaps& gaps) {
  std::mt19937 rng(err.seed);
  std::normal_distribution<double> n01(0.0, 1.0);
  // Draws are sequenced z, y, x (the order x86-64 GCC evaluated the former
  // constructor arguments in, which are unsequenced: aarch64 GCC goes x, y, z),
  // so every architecture runs the same noise and the thresholds below hold for
  // the realisations they were measured on.
  auto draw3 = [](auto&& draw) {
    const double z = draw(), y = draw(), x = draw();
    return Eigen::Vector3d(x, y, z);
  };
  auto sign = [&rng] { return (rng() & 1u) != 0u ? 1.0 : -1.0; };
  const Eigen::Vector3d bg = err.gyro_bias_rad_s * draw3(sign);
  const Eigen::Vector3d ba = err.accel_bias_m_s2 * draw3(sign);
  auto noise3 = [&](double s) -> Eigen::Vector3d { return s * draw3([&] { return n01(rng); }); };

  est::InMotionAlignment align;
  align.configure(cfg);
  Outcome o;
  double last_window = 0.0, t_prev_imu = 0.0;
  const double t0 = tr.truth.front().nav.t_s;
  const auto i0 = static_cast<std::size_t>(std::lround((t_start_s - t0) * kImuHz)) / kGnssEvery * kGnssEvery;
  const auto i1 = std::min(tr.truth.size(), i0 + static_cast<std::size_t>(std::lround(duration_s * kImuHz)));
  for (std::size_t i = i0; i < i1; ++i) {
    est::ImuSample s = tr.truth[i].imu;
    s.angular_rate_b_rad_s += bg + noise3(err.gyro_white_rad_s);
    s.specific_force_b_m_s2 += ba + noise3(err.accel_white_m_s2);
    const double t = s.t_s, since = t - tr.truth[i0].nav.t_s;
    if (t >= gaps.imu_from_s && t < gaps.imu_to_s) continue;
    align.add_imu(s, i == i0 ? 1.0 / kImuHz : t - t_prev_imu);
    t_prev_imu = t;
    if (i % kGnssEvery != 0 || (t >= gaps.gnss_from_s && t < gaps.gnss_to_s)) continue;
    est::GnssObservation z = tr.gnss[i / kGnssEvery];
    const double ve = n01(rng), vn = n01(rng);  // sequenced as above
    z.v_ne_m_s += err.gnss_vel_sigma_m_s * Eigen::Vector2d(vn, ve);
    z.h_m += err.gnss_h_sigma_m * n01(rng);
    est::InMotionSolution sol;
    if (!align.add_gnss(z, t, sol)) continue;

    ++o.solutions;
    if (o.first_solution_s < 0.0) o.first_solution_s = since;
    if (sol.window_s < last_window) ++o.restarts;
    last_window = sol.window_s;
    o.max_window_s = std::max(o.max_window_s, sol.window_s);
    if (o.first_after_gap_s < 0.0 && gaps.gnss_to_s > gaps.gnss_from_s && t >= gaps.gnss_to_s) {
      o.first_after_gap_s = t - gaps.gnss_to_s;
      o.window_after_gap_s = sol.window_s;
    }
    const Eigen::Vector3d e = attitude_error_ned(sol.q_nb, tr.truth[i].nav.q_nb);
    const double tilt = e.head<2>().norm(), tilt_sigma = sol.att_sigma_rad.head<2>().norm();
    o.max_tilt_err_rad = std::max(o.max_tilt_err_rad, tilt);
    o.final_tilt_sigma_rad = tilt_sigma;
    o.final_yaw_sigma_rad = sol.att_sigma_rad.z();
    for (int q = 0; q < Outcome::kSnaps; ++q) {
      if (std::abs(since - (4.0 + 5.0 * q)) > 1e-6) continue;
      o.z.row(q) << tilt / tilt_sigma, std::abs(e.z()) / sol.att_sigma_rad.z();
    }
    if (sol.yaw_observable) {
      if (o.yaw_observable_s < 0.0) o.yaw_observable_s = since;
      o.max_yaw_err_rad = std::max(o.max_yaw_err_rad, std::abs(e.z()));
    }
    if (tilt_sigma < 3.0 * kDeg) {
      o.max_tilt_ratio = sol.yaw_observable ? std::max({o.max_tilt_ratio, std::abs(e.x()) / sol.att_sigma_rad.x(),
                                                        std::abs(e.y()) / sol.att_sigma_rad.y()})
                                            : std::max(o.max_tilt_ratio, tilt / tilt_sigma);
      if (sol.yaw_observable) o.max_yaw_ratio = std::max(o.max_yaw_ratio, std::abs(e.z()) / sol.att_sigma_rad.z());
      ++o.checked;
      const bool beyond = sol.yaw_observable ? (e.cwiseAbs() - 3.0 * sol.att_sigma_rad).maxCoeff() > 0.0
                                             : tilt > 3.0 * tilt_sigma;
      o.beyond_3_sigma += beyond ? 1 : 0;
      const Eigen::Vector3d bias_ratio = (sol.gyro_bias_rad_s - bg).cwiseAbs().cwiseQuotient(sol.gyro_bias_sigma_rad_s);
      if (sol.yaw_observable) o.max_gyro_bias_ratio = std::max(o.max_gyro_bias_ratio, bias_ratio.maxCoeff());
    }
  }
  return o;
}

void print(const char* name, const Outcome& o) {
  std::printf(
      "%-26s yaw-obs %5.1f s | max err tilt %8.5f yaw %8.5f deg | max err/sigma tilt %4.2f yaw %4.2f bg %4.2f | "
      "final sigma tilt %6.3f yaw %7.3f deg | restarts %d\n",
      name, o.yaw_observable_s, o.max_tilt_err_rad / kDeg, o.max_yaw_err_rad / kDeg, o.max_tilt_ratio,
      o.max_yaw_ratio, o.max_gyro_bias_ratio, o.final_tilt_sigma_rad / kDeg, o.final_yaw_sigma_rad / kDeg,
      o.restarts);
}

}  // namespace sinu::test
