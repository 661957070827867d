#include "firmware/cli/board_options.hpp"

namespace sinu::cli {

void ImuOptions::add_to(CLI::App& cmd) {
  cmd.add_option("--mounting", mounting, "IMU mounting: body FRD axes from chip axes, e.g. x,-y,-z")
      ->capture_default_str();
  cmd.add_option("--accel-range", accel_g, "Accelerometer full scale [g]")
      ->check(CLI::IsMember({2, 4, 8, 16}))
      ->capture_default_str();
  cmd.add_option("--gyro-range", gyro_dps, "Gyroscope full scale [deg/s]")
      ->check(CLI::IsMember({250, 500, 1000, 2000}))
      ->capture_default_str();
  cmd.add_option("--dlpf", dlpf, "Digital low-pass filter setting 0..7")->check(CLI::Range(0, 7))->capture_default_str();
  cmd.add_option("--imu-rate", odr_hz, "IMU output data rate [Hz]")->check(CLI::Range(4.5, 1125.0))->capture_default_str();
}

bool ImuOptions::to_config(drivers::Icm20948Config& cfg, std::string& error) const {
  const auto m = drivers::AxisMap::parse(mounting);
  if (!m) {
    error = "--mounting '" + mounting + "': expected a signed permutation of x,y,z such as x,-y,-z";
    return false;
  }
  cfg.mounting = *m;
  cfg.accel_range = accel_g == 2 ? drivers::AccelRange::G2
                    : accel_g == 4 ? drivers::AccelRange::G4
                    : accel_g == 8 ? drivers::AccelRange::G8
                                   : drivers::AccelRange::G16;
  cfg.gyro_range = gyro_dps == 250   ? drivers::GyroRange::Dps250
                   : gyro_dps == 500 ? drivers::GyroRange::Dps500
                   : gyro_dps == 1000 ? drivers::GyroRange::Dps1000
                                      : drivers::GyroRange::Dps2000;
  cfg.dlpf = static_cast<std::uint8_t>(dlpf);
  cfg.odr_hz = odr_hz;
  return true;
}

}  // namespace sinu::cli
