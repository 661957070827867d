#pragma once
// sinu simulate: a flight (imu.csv, gps.nmea, truth.csv, meta.json) or a
// static bench session (imu.csv, meta.json) in the dataset folder format,
// and the hidden truth (error-model parameters, effects) as JSON elsewhere.
#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "firmware/host/dataset/diagnostic.hpp"
#include "firmware/host/sim/airframe.hpp"
#include "firmware/host/sim/effects.hpp"
#include "firmware/host/sim/gps_receiver.hpp"
#include "firmware/host/sim/imu_error_model.hpp"

namespace sinu::sim {

enum class SimMode { Flight, Static };

struct SimOptions {
  SimMode mode = SimMode::Flight;
  std::string out_dir;
  std::uint64_t seed = 1;
  double duration_s = 1800.0;
  double imu_rate_hz = 40.0;
  double gps_rate_hz = 5.0;
  Effects effects;
  Airframe airframe = Airframe::FixedWing;  // flight only: what flies it (airframe.hpp)
  /// Static only: 1 = the level bench; N in 6..26 = N attitudes
  /// (bench_schedule.hpp), each held `hold_s` (0: the duration split evenly),
  /// with `transition_s` of turning between them.
  std::size_t positions = 1;
  double hold_s = 0.0;
  double transition_s = 4.0;
  /// Draw the unit's accelerometer scale factors and misalignment from the
  /// seed where `effects` gives none (draw_unit_accel_errors).
  bool unit_accel_errors = false;
  /// Replaces the drawn default model (tests: ideal_imu_error_model()).
  std::optional<ImuErrorModel> error_model;
  GpsErrorModel gps;
  /// Replaces the drawn site's latitude, longitude [deg] and ground height [m]
  /// (high latitudes, the date line); the rest of the draw is unchanged.
  std::optional<std::array<double, 3>> site_lat_lon_h;
  /// Internal trajectory rate is at least this [Hz] (a multiple of the IMU rate).
  double min_internal_rate_hz = 800.0;
};

struct SimResult {
  nlohmann::json hidden;  // everything the dataset does not say (schema: docs/simulation.md)
  std::uint64_t imu_rows = 0, gps_sentences = 0, corrupted_sentences = 0;
};

/// The session's length: `duration_s`, or N holds and N - 1 transitions when `hold_s` is given.
double session_duration_s(const SimOptions& o);
/// Checks option ranges; false with a message naming the option.
bool validate_options(const SimOptions& o, std::string& why);
/// Writes the dataset into o.out_dir (created if needed).
bool run_simulation(const SimOptions& o, SimResult& result, dataset::Diagnostic& err);

}  // namespace sinu::sim
