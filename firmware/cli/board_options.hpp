#pragma once
// Command-line options shared by the modes that run the board's sensor loop
// (fly, record, convert).
#include <CLI/CLI.hpp>
#include <string>

#include "drivers/imu/icm20948.hpp"

namespace sinu::cli {

struct ImuOptions {
  std::string mounting = "x,-y,-z";  // chip axes -> FRD (chip flat, component side up)
  int accel_g = 8, gyro_dps = 1000, dlpf = 5;
  double odr_hz = 40.0;
  void add_to(CLI::App& cmd);
  bool to_config(drivers::Icm20948Config& cfg, std::string& error) const;
};

}  // namespace sinu::cli
