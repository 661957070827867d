#pragma once
// The navigator's health, per output and in total. Every output carries
// `flags`: state bits (what holds now) and event bits (what happened since
// the previous output). Writers OR the flags of the outputs they thin out,
// so no event between two nav.csv rows is lost.
#include <array>
#include <cstdint>

namespace sinu::est {

enum class AidingSource : std::uint8_t { GnssPosition, GnssVelocity, Magnetometer, ZeroVelocity, Nonholonomic };
inline constexpr std::size_t kAidingSourceCount = 5;
inline constexpr std::array<const char*, kAidingSourceCount> kAidingSourceNames = {
    "gnss_position", "gnss_velocity", "magnetometer", "zero_velocity", "nonholonomic"};

namespace nav_flag {
enum : std::uint32_t {
  // state
  kAligned = 1u << 0,        // a navigation solution exists
  kGnssTimeout = 1u << 1,    // no GNSS position for gnss_timeout_s: dead reckoning
  kMagTimeout = 1u << 2,     // magnetometer states on, no field sample for mag_timeout_s
  kLost = 1u << 3,           // fixes arriving, none fused (rejected, or too late to use) for lost_after_s: the filter is wrong
  kGnssSuspect = 1u << 4,    // GNSS position rejected while its velocity agrees: a GNSS jump, held off
  kClipping = 1u << 5,       // an IMU axis is (or was within the filter's memory of it) at full scale
  kGroundVehicle = 1u << 6,  // the ground-vehicle constraints are in use (configured or detected)
  // events
  kGnssPosFused = 1u << 8,
  kGnssPosRejected = 1u << 9,
  kGnssVelFused = 1u << 10,
  kGnssVelRejected = 1u << 11,
  kMagFused = 1u << 12,
  kMagRejected = 1u << 13,
  kPositionReset = 1u << 14,  // position (and velocity) reset to GNSS
  kVelocityReset = 1u << 15,
  kYawReset = 1u << 16,
  kImuGap = 1u << 17,         // the interval to this sample was longer than a few sample periods
  kImuDropped = 1u << 18,     // a raw sample was dropped: non-finite value, or time not increasing
  kAlignedNow = 1u << 19,     // the alignment completed at this output
  kStill = 1u << 20,          // state: standing still (IMU quiet, GNSS speed ~0): zero-velocity updates
  kNonholonomicFused = 1u << 21,
  kVehicleChanged = 1u << 22,  // vehicle auto: the ground-vehicle constraints were switched on or off
  kGyroBiasReleased = 1u << 23,  // the gyro bias about the vertical widened (the magnetometer's misfit on one side, a yaw reset)
  kCourseTurned = 1u << 24,      // aligned on the GNSS course, turned to the in-motion alignment's yaw (coarse_alignment.hpp)
};
}  // namespace nav_flag

/// The flags' names, bit by bit (nav.csv documents its `flags` column with them).
inline constexpr std::array<const char*, 25> kNavFlagNames = {
    "aligned", "gnss_timeout", "mag_timeout", "lost", "gnss_suspect", "clipping", "ground_vehicle", "",
    "gnss_pos_fused", "gnss_pos_rejected", "gnss_vel_fused", "gnss_vel_rejected", "mag_fused", "mag_rejected",
    "position_reset", "velocity_reset", "yaw_reset", "imu_gap", "imu_dropped", "aligned_now", "still",
    "nonholonomic_fused", "vehicle_changed", "gyro_bias_released", "course_turned"};

struct NavCounters {
  std::array<std::uint64_t, kAidingSourceCount> accepted{}, rejected{};
  std::uint64_t gnss_late = 0;           // arrived after the horizon had passed its time
  std::uint64_t gnss_overflow = 0;       // buffer full
  std::uint64_t imu_non_increasing = 0;  // dropped: time not after the previous sample
  std::uint64_t imu_invalid = 0;         // dropped: non-finite values
  std::uint64_t imu_gaps = 0;            // intervals longer than a few sample periods
  double imu_gap_total_s = 0.0;
  double imu_longest_gap_s = 0.0;
  std::uint64_t imu_clipped_samples = 0;  // raw samples with an axis at full scale
  std::uint64_t position_resets = 0, velocity_resets = 0, yaw_resets = 0;
  std::uint64_t vertical_resets = 0;     // of velocity_resets: vd to the GNSS heights' rate (vertical_check.hpp)
  std::uint64_t mag_reanchors = 0;       // hard iron re-anchored after a disturbance
  std::uint64_t gyro_bias_releases = 0;  // gyro bias about the vertical widened: the heading check, a yaw reset
  std::uint64_t position_inflations = 0;  // position widened by a small misfit, the epoch fused again
  std::uint64_t gnss_bias_holds = 0;     // the receiver's correlated error held after a disturbance (Navigator::disturbed)
  std::uint64_t horizontal_fixes = 0;    // fixes without a height (RMC or GLL alone) fused north and east
  std::uint64_t course_held = 0;         // velocities whose course the receiver held at low speed: speed only
  std::uint64_t gnss_timeouts = 0;       // times the GNSS position stopped for gnss_timeout_s
  double gnss_timeout_total_s = 0.0;     // time spent dead reckoning
  double lost_total_s = 0.0;             // time flagged lost
  double first_lost_t_s = 0.0;           // valid when lost_total_s > 0
  double first_reset_t_s = 0.0;          // valid when any reset happened
  std::uint64_t resets() const { return position_resets + velocity_resets + yaw_resets; }
};

}  // namespace sinu::est
