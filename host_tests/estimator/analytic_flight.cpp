#include "host_tests/estimator/analytic_flight.hpp"

#include <cmath>
#include <numbers>

#include "estimator/earth/wgs84.hpp"
#include "estimator/ins/rotation.hpp"

namespace sinu::test {

namespace w = est::wgs84;
constexpr double kPi = std::numbers::pi;

namespace {
double smooth(double x) {  // 0 -> 1, zero slope at both ends
  if (x <= 0.0) return 0.0;
  if (x >= 1.0) return 1.0;
  return x * x * (3.0 - 2.0 * x);
}
}  // namespace

double AnalyticFlight::speed(double t) const {
  if (p_.stationary) return 0.0;
  const double tr = t - p_.t0_s - p_.rest_s;
  const double t1 = tr - 20.0;
  return p_.cruise_m_s * smooth(tr / 20.0) + (t1 > 0.0 ? 4.0 * (1.0 - std::cos(2.0 * kPi * t1 / 300.0)) : 0.0);
}
double AnalyticFlight::yaw(double t) const {
  const double t1 = t - p_.t0_s - p_.rest_s - 20.0;
  if (p_.stationary || t1 <= 0.0) return p_.yaw0_rad;
  const double c = 1.0 - std::cos(2.0 * kPi * t1 / 200.0);
  return p_.yaw0_rad + 1.5 * c * c;
}
double AnalyticFlight::yaw_rate(double t) const {
  const double t1 = t - p_.t0_s - p_.rest_s - 20.0;
  if (p_.stationary || t1 <= 0.0) return 0.0;
  const double om = 2.0 * kPi / 200.0;
  return 1.5 * 2.0 * (1.0 - std::cos(om * t1)) * om * std::sin(om * t1);
}
double AnalyticFlight::flight_path(double t) const {
  const double t1 = t - p_.t0_s - p_.rest_s - 20.0;
  if (p_.stationary || t1 <= 0.0) return 0.0;
  return 0.04 * (1.0 - std::cos(2.0 * kPi * t1 / 150.0)) - 0.02 * (1.0 - std::cos(4.0 * kPi * t1 / 150.0));
}

Eigen::Vector3d AnalyticFlight::velocity_n(double t) const {
  const double v = speed(t), psi = yaw(t), gam = flight_path(t);
  return {v * std::cos(psi) * std::cos(gam), v * std::sin(psi) * std::cos(gam), -v * std::sin(gam)};
}

Eigen::Quaterniond AnalyticFlight::attitude(double t) const {
  const double roll = 0.01 + std::atan(speed(t) * yaw_rate(t) / 9.8);
  const double pitch = 0.02 + flight_path(t) + (p_.stationary ? 0.0 : 0.03 * smooth((t - p_.t0_s - p_.rest_s) / 20.0));
  return est::quat_from_euler(roll, pitch, yaw(t));
}

std::vector<TruthSample> AnalyticFlight::sample(double rate_hz, double duration_s) const {
  constexpr double kStep = 1e-3, kH = 1e-3;
  const auto per_sample = static_cast<long>(std::lround(1.0 / (rate_hz * kStep)));
  const auto n_steps = static_cast<long>(std::lround(duration_s / kStep));
  std::vector<TruthSample> out;
  out.reserve(static_cast<std::size_t>(n_steps / per_sample + 1));
  Eigen::Vector3d pos(p_.lat0_deg * kPi / 180.0, p_.lon0_deg * kPi / 180.0, p_.h0_m);
  auto deriv = [this](double t, const Eigen::Vector3d& x) {
    const Eigen::Vector3d v = velocity_n(t);
    return Eigen::Vector3d(v.x() / (w::meridian_radius_m(x.x()) + x.z()),
                           v.y() / ((w::transverse_radius_m(x.x()) + x.z()) * std::cos(x.x())), -v.z());
  };
  for (long k = 0; k <= n_steps; ++k) {
    const double t = p_.t0_s + static_cast<double>(k) * kStep;
    if (k % per_sample == 0) {
      TruthSample s;
      s.nav.t_s = t;
      s.nav.lat_rad = pos.x();
      s.nav.lon_rad = pos.y();
      s.nav.h_m = pos.z();
      s.nav.v_n_m_s = velocity_n(t);
      s.nav.q_nb = attitude(t);
      const Eigen::Vector3d w_ie = w::omega_ie_n(pos.x());
      const Eigen::Vector3d w_en = w::omega_en_n(pos.x(), pos.z(), s.nav.v_n_m_s);
      const Eigen::Vector3d vdot = (velocity_n(t + kH) - velocity_n(t - kH)) / (2.0 * kH);
      const Eigen::Vector3d g(0.0, 0.0, w::normal_gravity_m_s2(pos.x(), pos.z()));
      const Eigen::Vector3d f_n = vdot - g + (2.0 * w_ie + w_en).cross(s.nav.v_n_m_s);
      const Eigen::Matrix3d C = s.nav.q_nb.toRotationMatrix();
      const Eigen::Matrix3d dC = attitude(t - kH).toRotationMatrix().transpose() * attitude(t + kH).toRotationMatrix();
      const Eigen::AngleAxisd aa(dC);
      const Eigen::Vector3d w_nb = aa.axis() * aa.angle() / (2.0 * kH);
      s.imu.t_s = t;
      s.imu.specific_force_b_m_s2 = C.transpose() * f_n;
      s.imu.angular_rate_b_rad_s = w_nb + C.transpose() * (w_ie + w_en);
      out.push_back(s);
    }
    const Eigen::Vector3d k1 = deriv(t, pos);
    const Eigen::Vector3d k2 = deriv(t + kStep / 2, pos + kStep / 2 * k1);
    const Eigen::Vector3d k3 = deriv(t + kStep / 2, pos + kStep / 2 * k2);
    const Eigen::Vector3d k4 = deriv(t + kStep, pos + kStep * k3);
    pos += kStep / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return out;
}

std::vector<est::GnssObservation> AnalyticFlight::gnss(const std::vector<TruthSample>& truth, std::size_t every,
                                                       double latency_s, const Eigen::Vector3d& lever_b,
                                                       double sigma_pos, double sigma_vel) {
  std::vector<est::GnssObservation> out;
  for (std::size_t i = 0; i < truth.size(); i += every) {
    const est::NavState& n = truth[i].nav;
    const Eigen::Vector3d l_n = n.C_nb() * lever_b;
    est::GnssObservation z;
    z.arrival_s = n.t_s + latency_s;
    z.has_position = true;
    z.lat_rad = n.lat_rad + l_n.x() / (w::meridian_radius_m(n.lat_rad) + n.h_m);
    z.lon_rad = n.lon_rad + l_n.y() / ((w::transverse_radius_m(n.lat_rad) + n.h_m) * std::cos(n.lat_rad));
    z.h_m = n.h_m - l_n.z();
    z.sigma_ned_m = Eigen::Vector3d::Constant(sigma_pos);
    z.has_velocity = true;
    // Antenna velocity: v + C_nb (w_nb x l); w_ib differs from w_nb by < 1e-4 rad/s here (Earth + transport rate).
    z.v_ne_m_s = (n.v_n_m_s + n.C_nb() * truth[i].imu.angular_rate_b_rad_s.cross(lever_b)).head<2>();
    z.sigma_vel_m_s = sigma_vel;
    out.push_back(z);
  }
  return out;
}

Eigen::Vector3d position_error_ned(const est::NavState& e, const est::NavState& t) {
  return {(e.lat_rad - t.lat_rad) * (w::meridian_radius_m(t.lat_rad) + t.h_m),
          (e.lon_rad - t.lon_rad) * (w::transverse_radius_m(t.lat_rad) + t.h_m) * std::cos(t.lat_rad),
          -(e.h_m - t.h_m)};
}

double attitude_error_rad(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  return Eigen::AngleAxisd(a * b.conjugate()).angle();
}

}  // namespace sinu::test
