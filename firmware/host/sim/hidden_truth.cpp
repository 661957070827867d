#include "firmware/host/sim/hidden_truth.hpp"

namespace sinu::sim {

namespace {

using nlohmann::json;

json per_axis(const TriadErrorModel& t, double AxisErrorModel::*field) {
  return json::array({t.axis[0].*field, t.axis[1].*field, t.axis[2].*field});
}

json triad_json(const TriadErrorModel& t) {
  return {{"white_noise_density", per_axis(t, &AxisErrorModel::white_noise_density)},
          {"gm_sigma", per_axis(t, &AxisErrorModel::gm_sigma)},
          {"gm_tau_s", per_axis(t, &AxisErrorModel::gm_tau_s)},
          {"periodic_sigma", per_axis(t, &AxisErrorModel::periodic_sigma)},
          {"periodic_period_s", per_axis(t, &AxisErrorModel::periodic_period_s)},
          {"periodic_damping", per_axis(t, &AxisErrorModel::periodic_damping)},
          {"rate_random_walk", per_axis(t, &AxisErrorModel::rate_random_walk)},
          {"turn_on_bias", per_axis(t, &AxisErrorModel::turn_on_bias)},
          {"quantisation_step", t.quantisation_step},
          {"full_scale", t.full_scale}};
}

json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }

}  // namespace

json imu_error_model_json(const ImuErrorModel& m) {
  return {{"accel", triad_json(m.accel)},
          {"gyro", triad_json(m.gyro)},
          {"mag", {{"white_noise_sigma_uT", m.mag.white_noise_sigma_uT}, {"quantisation_step_uT", m.mag.quantisation_step_uT}}},
          {"temp",
           {{"white_noise_sigma_degC", m.temp.white_noise_sigma_degC},
            {"quantisation_step_degC", m.temp.quantisation_step_degC}}}};
}

json gps_error_model_json(const GpsErrorModel& m) {
  return {{"position_white_sigma_ned_m", vec(m.white_sigma_ned_m)},
          {"position_gm_sigma_ned_m", vec(m.gm_sigma_ned_m)},
          {"position_gm_tau_s", m.gm_tau_s},
          {"velocity_white_sigma_ned_m_s", vec(m.velocity_sigma_ned_m_s)},
          {"base_latency_s", m.base_latency_s},
          {"sentence_spacing_s", m.sentence_spacing_s},
          {"corrupt_fraction", m.corrupt_fraction}};
}

json temperature_json(const TemperatureProfile& p) {
  return {{"ambient_degC", p.ambient_degC},
          {"warmup_rise_degC", p.warmup_rise_degC},
          {"warmup_tau_s", p.warmup_tau_s},
          {"cycle_amplitude_degC", p.cycle_amplitude_degC},
          {"cycle_period_s", p.cycle_period_s}};
}

}  // namespace sinu::sim
