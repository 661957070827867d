#include "firmware/board/config/fly_setup.hpp"

#include <algorithm>
#include <numbers>

#include "firmware/board/config/vehicle_words.hpp"
#include "firmware/board/nav_unit.hpp"

namespace sinu::board {

namespace {
std::string join(const std::vector<std::string>& words) {
  std::string s;
  for (const std::string& w : words) s += (s.empty() ? "" : ",") + w;
  return s;
}
}  // namespace

bool imu_config(const FlyConfig::Imu& imu, drivers::Icm20948Config& cfg, std::string& error) {
  const auto m = drivers::AxisMap::parse(imu.mounting);
  if (!m) {
    error = "imu.mounting '" + imu.mounting + "': expected a signed permutation of x,y,z such as x,-y,-z";
    return false;
  }
  cfg.address = static_cast<std::uint8_t>(imu.address);
  cfg.mounting = *m;
  cfg.accel_range = imu.accel_range_g == 2   ? drivers::AccelRange::G2
                    : imu.accel_range_g == 4 ? drivers::AccelRange::G4
                    : imu.accel_range_g == 8 ? drivers::AccelRange::G8
                                             : drivers::AccelRange::G16;
  cfg.gyro_range = imu.gyro_range_dps == 250    ? drivers::GyroRange::Dps250
                   : imu.gyro_range_dps == 500  ? drivers::GyroRange::Dps500
                   : imu.gyro_range_dps == 1000 ? drivers::GyroRange::Dps1000
                                                : drivers::GyroRange::Dps2000;
  cfg.dlpf = static_cast<std::uint8_t>(imu.dlpf);
  cfg.odr_hz = imu.rate_hz;
  return true;
}

bool nav_unit_config(const FlyConfig& c, NavUnitConfig& out, std::string& error) {
  const FlyConfig::Navigation& n = c.navigation;  // fields not in sinu.toml keep `out`'s values
  out.calib_path = n.calibration;
  out.model_path = n.model_file;
  out.state_path = n.state_file;
  if (n.model == "gm") out.calib.kind = est::NoiseModelKind::GaussMarkov;
  else if (n.model == "ar") out.calib.kind = est::NoiseModelKind::AutoRegressive;
  else return (error = "navigation.model must be gm or ar, not '" + n.model + "'"), false;
  if (!resolve_effects(join(n.effects), join(n.without_effects), out.effects, error)) return false;
  if (!vehicle_from_word(n.vehicle, out.vehicle))
    return (error = "navigation.vehicle must be air, ground or auto, not '" + n.vehicle + "'"), false;
  out.use_mag = n.magnetometer;
  if (n.mag_declination_deg) out.mag_declination_deg = *n.mag_declination_deg;
  out.gps_latency_s = n.gps_latency_s;
  out.imu_latency_s = n.imu_latency_s;
  out.accel_bias_walk_scale = n.accel_bias_walk_scale;
  out.gyro_bias_walk_scale = n.gyro_bias_walk_scale;
  drivers::Icm20948Config imu;
  if (!imu_config(c.imu, imu, error)) return false;
  full_scales(imu, out.accel_range_m_s2, out.gyro_range_rad_s);
  return true;
}

MavlinkOutputConfig mavlink_output_config(const FlyConfig::Mavlink& m) {
  MavlinkOutputConfig out;
  out.system_id = static_cast<std::uint8_t>(m.system_id);
  out.component_id = static_cast<std::uint8_t>(m.component_id);
  out.odometry_hz = m.odometry ? m.rate_hz : 0.0;
  out.gps_input_hz = m.gps_input ? std::min(m.rate_hz, 5.0) : 0.0;  // a GPS's rate: the autopilot's GPS driver expects <= 5-10 Hz
  return out;
}

NmeaOutputConfig nmea_output_config(const FlyConfig::Nmea& n) {
  NmeaOutputConfig out;
  out.rate_hz = n.rate_hz;
  out.talker = n.talker == "GN" ? NmeaTalker::GN : NmeaTalker::GP;
  return out;
}

}  // namespace sinu::board
