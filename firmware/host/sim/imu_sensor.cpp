#include "firmware/host/sim/imu_sensor.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "estimator/earth/wgs84.hpp"

namespace sinu::sim {

namespace {

double quantise(double x, double step) { return step > 0.0 ? std::round(x / step) * step : x; }

/// (I + diag(s)) (I + M): a scale on each axis after the cross-axis mixing.
Eigen::Matrix3d gain(const Eigen::Vector3d& scale, const Eigen::Matrix3d& misalign) {
  Eigen::Matrix3d s = Eigen::Matrix3d::Identity();
  s.diagonal() += scale;
  return s * (Eigen::Matrix3d::Identity() + misalign);
}

}  // namespace

void TriadErrors::init(const TriadErrorModel& m, double dt, Rng& rng) {
  model_ = m;
  for (std::size_t i = 0; i < 3; ++i) {
    const AxisErrorModel& a = m.axis[i];
    white_sigma_[i] = a.white_noise_density / std::sqrt(dt);
    gm_[i].init(a.gm_sigma, a.gm_tau_s, dt, rng);
    periodic_[i].init(a.periodic_sigma, a.periodic_period_s, a.periodic_damping, dt, rng);
    rrw_[i].init(a.rate_random_walk, dt);
  }
}

Eigen::Vector3d TriadErrors::step(Rng& rng) {
  Eigen::Vector3d e;
  for (std::size_t i = 0; i < 3; ++i)
    e[static_cast<Eigen::Index>(i)] = model_.axis[i].turn_on_bias + white_sigma_[i] * rng.normal() +
                                      gm_[i].step(rng) + periodic_[i].step(rng) + rrw_[i].step(rng);
  return e;
}

Eigen::Vector3d TriadErrors::measure(const Eigen::Vector3d& v) const {
  Eigen::Vector3d q;
  const double fs = model_.full_scale;
  for (Eigen::Index i = 0; i < 3; ++i) {
    const double x = quantise(v[i], model_.quantisation_step);
    q[i] = fs > 0.0 ? std::clamp(x, -fs, fs) : x;
  }
  return q;
}

ImuSensor::ImuSensor(const ImuErrorModel& model, const Effects& fx, const Eigen::Vector3d& earth_field_n_uT, double dt,
                     Rng& noise_rng)
    : model_(model), rng_(noise_rng) {
  accel_.init(model.accel, dt, rng_);
  gyro_.init(model.gyro, dt, rng_);
  const effects::SensorEffects e = sensor_effects(fx);
  accel_gain_ = gain(e.accel_scale, e.accel_misalign);
  gyro_gain_ = gain(e.gyro_scale, e.gyro_misalign);
  g_sensitivity_ = e.gyro_g_sensitivity;
  mag_axes_ = e.mag_soft_iron * e.mag_axes;
  accel_temp_k_ = e.accel_temp_per_degC;
  gyro_temp_k_ = e.gyro_temp_per_degC;
  hard_iron_ = e.mag_hard_iron_uT;
  motor_field_ = e.mag_motor_uT_per_m_s2;
  mag_latency_s_ = e.mag_latency_s;
  earth_field_n_uT_ = earth_field_n_uT;
}

ImuOutput ImuSensor::sample(const Eigen::Vector3d& f_b, const Eigen::Vector3d& w_b, const Eigen::Matrix3d& C_nb,
                            double temp_degC) {
  const double dT = temp_degC - kTempBiasReference_degC;
  ImuOutput out;
  out.specific_force_b_m_s2 = accel_.measure(accel_gain_ * f_b + accel_.step(rng_) + accel_temp_k_ * dT);
  out.angular_rate_b_rad_s =
      gyro_.measure(gyro_gain_ * w_b + g_sensitivity_ * f_b + gyro_.step(rng_) + gyro_temp_k_ * dT);
  // A late reading: the body field of mag_latency_s ago, turned back by the rate over it.
  const double turn_rad = w_b.norm() * mag_latency_s_;
  const Eigen::Matrix3d back = turn_rad > 0.0 ? Eigen::AngleAxisd(turn_rad, w_b.normalized()).toRotationMatrix()
                                              : Eigen::Matrix3d::Identity();
  const Eigen::Vector3d m = mag_axes_ * (back * C_nb.transpose() * earth_field_n_uT_) + hard_iron_ +
                            motor_field_ * (-f_b.z() - est::wgs84::kStandardGravity);
  const double mag_sigma = model_.mag.white_noise_sigma_uT, mag_q = model_.mag.quantisation_step_uT;
  for (Eigen::Index i = 0; i < 3; ++i) out.mag_b_uT[i] = quantise(m[i] + mag_sigma * rng_.normal(), mag_q);
  out.temp_degC =
      quantise(temp_degC + model_.temp.white_noise_sigma_degC * rng_.normal(), model_.temp.quantisation_step_degC);
  return out;
}

}  // namespace sinu::sim
