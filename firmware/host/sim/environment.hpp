#pragma once
// Slowly varying surroundings of the IMU: die temperature and the Earth's
// magnetic field.
#include <Eigen/Core>

#include "firmware/host/sim/rng.hpp"

namespace sinu::sim {

/// T(s) = ambient + rise (1 - exp(-s / tau)) + cycle_amplitude sin(2 pi s / cycle_period),
/// s = seconds since power-on.
struct TemperatureProfile {
  double ambient_degC = 20.0;
  double warmup_rise_degC = 0.0;
  double warmup_tau_s = 600.0;
  double cycle_amplitude_degC = 0.0;
  double cycle_period_s = 3600.0;
  double at(double since_power_on_s) const;
};

/// In flight: the die warms up by 10-18 degC over ~10 minutes, no cycle.
TemperatureProfile draw_flight_temperature(Rng& rng);
/// On the bench: a few degC of warm-up and a slow room (air-conditioning)
/// cycle of 0.5-1 degC with a period of 1-2 h.
TemperatureProfile draw_bench_temperature(Rng& rng);

/// The Earth field in NED [uT] at a site and date: the World Magnetic Model's
/// main field (what a real unit there measures, less crustal anomalies), so
/// the declination a navigator takes from the same model is the true one.
Eigen::Vector3d earth_field_n_uT(double lat_rad, double lon_rad, double h_m, double decimal_year);
/// A bench has no GNSS to date it: its field is the model's at this epoch.
inline constexpr double kBenchDecimalYear = 2025.5;

}  // namespace sinu::sim
