#include "firmware/host/sim/imu_error_model.hpp"

#include <cmath>
#include <numbers>

namespace sinu::sim {

namespace {

constexpr double kG0 = 9.80665;                        // standard gravity [m/s^2]
constexpr double kDegToRad = std::numbers::pi / 180.0;
constexpr double kAdcCounts = 65536.0;                 // 16-bit output

// Nominal accelerometer values (ICM-20948 datasheet: 230 ug/sqrt(Hz) noise,
// +-4 g range after the board's power-on self-calibration).
constexpr double kAccelFullScale = 4.0 * kG0;
constexpr double kAccelWhite = 230e-6 * kG0;            // [m/s^2/sqrt(Hz)]
constexpr double kAccelTurnOnSpread = 0.06;              // [m/s^2] 1-sigma (~6 mg)
constexpr double kAccelGmSigma = 2.0e-3;                 // [m/s^2]
constexpr double kAccelPeriodicSigma = 6.0e-3;           // [m/s^2] dominates the denoised error
constexpr double kAccelRrw = 1.5e-5;                     // [m/s^2/sqrt(s)]

// Nominal gyroscope values (ICM-20948: 0.015 dps/sqrt(Hz), +-500 dps range).
constexpr double kGyroFullScale = 500.0 * kDegToRad;
constexpr double kGyroWhite = 0.015 * kDegToRad;         // [rad/s/sqrt(Hz)]
constexpr double kGyroTurnOnSpread = 0.2 * kDegToRad;    // [rad/s] 1-sigma
constexpr double kGyroGmSigma = 2.0e-4;                  // [rad/s] (~40 deg/h)
constexpr double kGyroPeriodicSigma = 6.0e-4;            // [rad/s]
constexpr double kGyroRrw = 1.0e-6;                      // [rad/s/sqrt(s)]

// The resonator periods span "seconds to a minute"; the damping keeps several
// oscillations visible in the autocorrelation (paper, Figs. 5-6).
constexpr double kPeriodMin_s = 4.0, kPeriodMax_s = 60.0;
constexpr double kDampingMin = 0.02, kDampingMax = 0.10;
constexpr double kGmTauMin_s = 100.0, kGmTauMax_s = 600.0;

// Per-unit spread of the nominal densities and sigmas (+-30 %).
constexpr double kSpreadLo = 0.7, kSpreadHi = 1.3;

TriadErrorModel draw_triad(Rng& rng, double full_scale, double white, double turn_on, double gm, double periodic,
                           double rrw) {
  TriadErrorModel t;
  t.full_scale = full_scale;
  t.quantisation_step = 2.0 * full_scale / kAdcCounts;
  for (AxisErrorModel& a : t.axis) {
    a.white_noise_density = white * rng.uniform(kSpreadLo, kSpreadHi);
    a.gm_sigma = gm * rng.uniform(kSpreadLo, kSpreadHi);
    a.gm_tau_s = rng.log_uniform(kGmTauMin_s, kGmTauMax_s);
    a.periodic_sigma = periodic * rng.uniform(kSpreadLo, kSpreadHi);
    a.periodic_period_s = rng.log_uniform(kPeriodMin_s, kPeriodMax_s);
    a.periodic_damping = rng.uniform(kDampingMin, kDampingMax);
    a.rate_random_walk = rrw * rng.uniform(kSpreadLo, kSpreadHi);
    a.turn_on_bias = turn_on * rng.normal();
  }
  return t;
}

}  // namespace

ImuErrorModel draw_default_imu_error_model(Rng& rng) {
  ImuErrorModel m;
  m.accel = draw_triad(rng, kAccelFullScale, kAccelWhite, kAccelTurnOnSpread, kAccelGmSigma, kAccelPeriodicSigma,
                       kAccelRrw);
  m.gyro = draw_triad(rng, kGyroFullScale, kGyroWhite, kGyroTurnOnSpread, kGyroGmSigma, kGyroPeriodicSigma, kGyroRrw);
  m.mag.white_noise_sigma_uT = 0.4;      // AK09916 rms noise at 0.15 uT/LSB
  m.mag.quantisation_step_uT = 0.15;
  m.temp.white_noise_sigma_degC = 0.02;
  m.temp.quantisation_step_degC = 1.0 / 333.87;
  return m;
}

ImuErrorModel ideal_imu_error_model() {
  ImuErrorModel m;
  m.accel.full_scale = 16.0 * kG0;  // wide enough never to clip a flight
  m.gyro.full_scale = 2000.0 * kDegToRad;
  return m;
}

}  // namespace sinu::sim
