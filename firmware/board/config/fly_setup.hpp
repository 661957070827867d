#pragma once
// sinu.toml's words (FlyConfig) made into the settings of the parts it
// configures: the ICM-20948 driver, the navigation unit, the outputs. One
// place, so the command line (which writes into the same FlyConfig) and the
// file mean the same.
#include <string>

#include "drivers/imu/icm20948.hpp"
#include "firmware/board/config/fly_config.hpp"
#include "firmware/board/nav_unit_config.hpp"
#include "firmware/board/outputs/mavlink_output.hpp"
#include "firmware/board/outputs/nmea_output.hpp"

namespace sinu::board {

/// False with `error` when a value has no driver setting (a mounting that
/// is no signed permutation; the config reader checks the rest).
bool imu_config(const FlyConfig::Imu& imu, drivers::Icm20948Config& out, std::string& error);
/// The navigation unit of `navigation` (into `out`, whose other fields stay),
/// with the IMU's full scales for the clipping screen.
bool nav_unit_config(const FlyConfig& config, NavUnitConfig& out, std::string& error);
MavlinkOutputConfig mavlink_output_config(const FlyConfig::Mavlink& mavlink);
NmeaOutputConfig nmea_output_config(const FlyConfig::Nmea& nmea);

}  // namespace sinu::board
