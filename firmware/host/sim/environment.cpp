#include "firmware/host/sim/environment.hpp"

#include "estimator/earth/geomagnetic_model.hpp"

#include <cmath>
#include <numbers>

namespace sinu::sim {

double TemperatureProfile::at(double s) const {
  return ambient_degC + warmup_rise_degC * (1.0 - std::exp(-s / warmup_tau_s)) +
         cycle_amplitude_degC * std::sin(2.0 * std::numbers::pi * s / cycle_period_s);
}

TemperatureProfile draw_flight_temperature(Rng& rng) {
  TemperatureProfile p;
  p.ambient_degC = rng.uniform(10.0, 30.0);
  p.warmup_rise_degC = rng.uniform(10.0, 18.0);
  p.warmup_tau_s = rng.uniform(400.0, 900.0);
  return p;
}

TemperatureProfile draw_bench_temperature(Rng& rng) {
  TemperatureProfile p;
  p.ambient_degC = rng.uniform(21.0, 25.0);
  p.warmup_rise_degC = rng.uniform(2.0, 5.0);
  p.warmup_tau_s = rng.uniform(600.0, 1200.0);
  p.cycle_amplitude_degC = rng.uniform(0.5, 1.0);
  p.cycle_period_s = rng.uniform(3600.0, 7200.0);
  return p;
}

Eigen::Vector3d earth_field_n_uT(double lat_rad, double lon_rad, double h_m, double decimal_year) {
  return est::geomag::geomagnetic_field(lat_rad, lon_rad, h_m, decimal_year).b_n_uT;
}

}  // namespace sinu::sim
