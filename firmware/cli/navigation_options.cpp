#include "firmware/cli/navigation_options.hpp"

#include "firmware/board/config/vehicle_words.hpp"

namespace sinu::cli {

void NavigationCliOptions::add_to(CLI::App& sub) {
  sub.add_option("--in", opt.in_dir,
                 "Dataset folder (imu.csv, gps.nmea, truth.csv), or a raw recording (sinu record, sinu convert) "
                 "replayed through the HAL and drivers")
      ->required();
  sub.add_option("--truth", opt.truth_path, "truth.csv to compare with (default: the dataset folder's, if any)");
  sub.add_option("--model-file", opt.unit.model_path,
                 "Effects known from an earlier flight, with values and sigmas (written by `sinu diagnose --apply`)");
  sub.add_option("--calib", opt.unit.calib_path,
                 "calib.json from `sinu calibrate`; omitted: built-in defaults (README, 'sinu replay')");
  sub.add_option("--model", model, "Sensor-error model: gm (GM1, 15 states) or ar (AR(p), 9+6p states)")
      ->capture_default_str();
  sub.add_option("--ar-rate", opt.unit.calib.ar_rate,
                 "AR models in calib.json at: model (the rate sinu calibrate chose by the Allan deviation over 1-100 s, "
                 "when it has one) or imu (fitted at the IMU rate)")
      ->capture_default_str();
  sub.add_option("--ar-method", opt.unit.calib.ar_method, "AR estimator in calib.json: burg, yule_walker, covariance")
      ->capture_default_str();
  sub.add_option("--ar-order", opt.unit.calib.ar_order, "AR order p (1..4)")->capture_default_str();
  app = &sub;
  sub.add_option("--effects", effects,
                 "Effect states added to the defaults (accel_bias, gyro_bias, gps_position_bias, gps_latency; "
                 "vocabulary: README, 'sinu replay')")
      ->capture_default_str();
  sub.add_option("--without-effects", without_effects,
                 "Default effect states to leave out (comma list, or none: no default effect)");
  sub.add_option("--gps-latency", opt.unit.gps_latency_s, "GPS latency: fix valid at arrival minus this [s]")
      ->capture_default_str();
  sub.add_option("--imu-latency", opt.unit.imu_latency_s,
                 "IMU samples stamped this much after the instant they describe [s] (diagnose says when)")
      ->capture_default_str()
      ->check(CLI::Range(0.0, 1.0));
  sub.add_option("--lever-arm", lever_arm, "Antenna minus IMU in body FRD [m], x,y,z")->delimiter(',');
  sub.add_option("--denoise", opt.unit.denoise,
                 "Wavelet denoiser in front of the INS: auto (calib.json's), none, or WAVELET:LEVELS (db4:3)")
      ->capture_default_str();
  sub.add_option("--gate", opt.unit.gate_sigma, "Innovation gate [sigma]")->capture_default_str();
  sub.add_option("--gps-vel-sigma", opt.unit.sigma.velocity_sigma_m_s,
                 "GNSS velocity noise per axis, 1 sigma [m/s] (NMEA carries none); given: kept fixed, else "
                 "learnt from the innovations starting here")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub.add_option("--gps-pos-sigma-scale", opt.unit.sigma.position_sigma_scale,
                 "GNSS position sigma: the receiver's (GST, or HDOP x UERE) times this (diagnose says when it is off); "
                 "without GST a factor is otherwise learnt from the innovations")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  for (const bool gyro : {false, true}) {
    sub.add_option(gyro ? "--gyro-bias-walk-scale" : "--accel-bias-walk-scale",
                   gyro ? opt.unit.gyro_bias_walk_scale : opt.unit.accel_bias_walk_scale,
                   std::string("The ") + (gyro ? "gyro" : "accelerometer") +
                       " bias states' random walk (calib.json's) times this: for a bias that moved in flight "
                       "(diagnose says when and by how much)")
        ->capture_default_str()
        ->check(CLI::PositiveNumber);
  }
  sub.add_option("--mag-sigma", opt.unit.mag_sigma_uT,
                 "Magnetometer noise per axis, 1 sigma [uT]; given: kept fixed, else learnt from the innovations")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub.add_option("--mag-declination", opt.unit.mag_declination_deg,
                 "Site's magnetic declination [deg, east +] for the heading from the magnetometer (default: the World "
                 "Magnetic Model's at the first fix, when the measured field is the Earth's; else from GNSS motion)");
  sub.add_option("--vehicle", vehicle,
                 "What carries the unit: auto (default: an aircraft until the solution's body-frame velocity shows "
                 "a ground vehicle: no sideways or vertical velocity), air (UAV), or ground (a car: the "
                 "non-holonomic constraint and zero-velocity updates at stops from the start)")
      ->capture_default_str();
  sub.add_flag("--no-mag", [this](std::int64_t) { opt.unit.use_mag = false; },
               "Do not fuse the magnetometer even when imu.csv has one");
  imu.add_imu(sub);
}

bool NavigationCliOptions::resolve(std::string& error) {
  if (model == "gm") {
    opt.unit.calib.kind = est::NoiseModelKind::GaussMarkov;
  } else if (model == "ar") {
    opt.unit.calib.kind = est::NoiseModelKind::AutoRegressive;
  } else {
    error = "--model must be gm or ar, not '" + model + "'";
    return false;
  }
  if (!board::resolve_effects(effects, without_effects, opt.unit.effects, error)) return false;
  if (!board::vehicle_from_word(vehicle, opt.unit.vehicle)) {
    error = "--vehicle must be air, ground or auto, not '" + vehicle + "'";
    return false;
  }
  // A dataset's full scales only when given (a recording's come from its driver settings).
  if (app && app->count("--gps-vel-sigma")) opt.unit.adapt_velocity_noise = false;
  if (app && app->count("--mag-sigma")) opt.unit.adapt_mag_noise = false;
  if (app && app->count("--gps-pos-sigma-scale")) opt.unit.adapt_position_scale = false;
  if (imu.given("--accel-range")) opt.unit.accel_range_m_s2 = imu.values.imu.accel_range_g * 9.80665;
  if (imu.given("--gyro-range")) opt.unit.gyro_range_rad_s = imu.values.imu.gyro_range_dps * 3.14159265358979323846 / 180.0;
  if (!lever_arm.empty()) {
    if (lever_arm.size() != 3) {
      error = "--lever-arm needs three numbers x,y,z [m]";
      return false;
    }
    opt.unit.lever_arm_b_m = {lever_arm[0], lever_arm[1], lever_arm[2]};
  }
  return imu.imu_config(opt.imu, error);
}

}  // namespace sinu::cli
