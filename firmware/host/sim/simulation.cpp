#include "firmware/host/sim/simulation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <numbers>

#include "estimator/earth/geomagnetic_model.hpp"
#include "firmware/host/dataset/dataset_paths.hpp"
#include "firmware/host/dataset/imu_csv.hpp"
#include "firmware/host/dataset/meta_json.hpp"
#include "firmware/host/dataset/truth_csv.hpp"
#include "firmware/host/calibration/bench_positions.hpp"
#include "firmware/host/sim/bench_schedule.hpp"
#include "firmware/host/sim/environment.hpp"
#include "firmware/host/sim/hidden_truth.hpp"
#include "firmware/host/sim/imu_sensor.hpp"
#include "firmware/host/sim/trajectory.hpp"

namespace sinu::sim {

namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr double kDegToRad = std::numbers::pi / 180.0;
// Past this the local-level (NED) frame turns too fast about the pole for a flight's steps.
constexpr double kMaxSiteLat_deg = 85.0;
constexpr double kMaxImuRate_hz = 1000.0, kMaxGpsRate_hz = 20.0;
constexpr double kMaxDuration_s = 48.0 * 3600.0;

void fill_imu_row(dataset::CsvRow& row, double t, const ImuOutput& o) {
  row.present = 0;
  row.set(dataset::imu_col::t, t);
  for (Eigen::Index i = 0; i < 3; ++i) {
    const auto k = static_cast<std::size_t>(i);
    row.set(dataset::imu_col::ax + k, o.specific_force_b_m_s2[i]);
    row.set(dataset::imu_col::gx + k, o.angular_rate_b_rad_s[i]);
    row.set(dataset::imu_col::mx + k, o.mag_b_uT[i]);
  }
  row.set(dataset::imu_col::temp, o.temp_degC);
}

void fill_truth_row(dataset::CsvRow& row, const TrueMotion& m) {
  row.present = 0;
  row.set(dataset::truth_col::t, m.t_s);
  row.set(dataset::truth_col::lat, m.lat_rad * kRadToDeg);
  row.set(dataset::truth_col::lon, std::remainder(m.lon_rad * kRadToDeg, 360.0));
  row.set(dataset::truth_col::h, m.h_m);
  // + 0.0 turns -0 into 0 so a still vehicle prints "0.0000", not "-0.0000".
  row.set(dataset::truth_col::vn, m.v_n_m_s.x() + 0.0);
  row.set(dataset::truth_col::ve, m.v_n_m_s.y() + 0.0);
  row.set(dataset::truth_col::vd, m.v_n_m_s.z() + 0.0);
  row.set(dataset::truth_col::roll, m.roll_rad * kRadToDeg);
  row.set(dataset::truth_col::pitch, m.pitch_rad * kRadToDeg);
  double yaw = std::remainder(m.yaw_rad * kRadToDeg, 360.0);
  if (yaw >= 180.0 - 5e-7) yaw -= 360.0;  // [-180, 180) after printing to 1e-6 deg
  row.set(dataset::truth_col::yaw, yaw);
}

bool writer_error(const dataset::Diagnostic& d, dataset::Diagnostic& err) {
  err = d;
  return false;
}

constexpr double kMinHold_s = 10.0;

nlohmann::json vec_json(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

// Each position held this long (multi-position static sessions).
double hold_of(const SimOptions& o) {
  const auto n = static_cast<double>(o.positions);
  return o.hold_s > 0.0 ? o.hold_s : (o.duration_s - (n - 1.0) * o.transition_s) / n;
}

nlohmann::json site_json(const Site& s) {
  return {{"lat_deg", s.lat_rad * kRadToDeg},
          {"lon_deg", s.lon_rad * kRadToDeg},
          {"ground_h_m", s.ground_h_m},
          {"heading_deg", s.heading_rad * kRadToDeg}};
}

}  // namespace

double session_duration_s(const SimOptions& o) {
  if (o.positions <= 1 || !(o.hold_s > 0.0)) return o.duration_s;
  const auto n = static_cast<double>(o.positions);
  return n * o.hold_s + (n - 1.0) * o.transition_s;
}

bool validate_options(const SimOptions& o, std::string& why) {
  if (!(o.imu_rate_hz >= 1.0 && o.imu_rate_hz <= kMaxImuRate_hz))
    return why = fmt::format("--imu-rate {} Hz is outside 1..{} Hz", o.imu_rate_hz, kMaxImuRate_hz), false;
  if (!(o.gps_rate_hz > 0.0 && o.gps_rate_hz <= kMaxGpsRate_hz))
    return why = fmt::format("--gps-rate {} Hz is outside 0..{} Hz", o.gps_rate_hz, kMaxGpsRate_hz), false;
  const double min_duration = o.mode == SimMode::Flight ? 300.0 : 1.0;
  const double duration = session_duration_s(o);
  if (!(duration >= min_duration && duration <= kMaxDuration_s))
    return why = fmt::format("duration {} s is outside {}..{} s", duration, min_duration, kMaxDuration_s), false;
  if (o.site_lat_lon_h) {
    const auto& [lat, lon, h] = *o.site_lat_lon_h;
    if (!(std::abs(lat) <= kMaxSiteLat_deg && std::abs(lon) <= 180.0 && h >= -500.0 && h <= 9000.0))
      return why = fmt::format("--site {},{},{}: latitude must be within +-{} deg, longitude +-180 deg, ground "
                               "height -500..9000 m", lat, lon, h, kMaxSiteLat_deg),
             false;
  }
  if (o.positions != 1) {
    if (o.mode == SimMode::Flight) return why = "--positions is for static sessions", false;
    if (o.positions < calibration::kFaces || o.positions > calibration::kMaxPositions)
      return why = fmt::format("--positions {} must be 1 (level) or {}..{} (the six faces, then tilted positions)",
                               o.positions, calibration::kFaces, calibration::kMaxPositions),
             false;
    if (!(o.transition_s >= 1.0 && o.transition_s <= 60.0))
      return why = fmt::format("--transition-s {} s is outside 1..60 s", o.transition_s), false;
    if (!(hold_of(o) >= kMinHold_s))
      return why = fmt::format("each of the {} positions would be held {:.1f} s: at least {} s is needed (a longer "
                               "--hours, or --hold-s)", o.positions, hold_of(o), kMinHold_s),
             false;
  }
  return true;
}

bool run_simulation(const SimOptions& options, SimResult& result, dataset::Diagnostic& err) {
  std::string why;
  if (!validate_options(options, why)) return writer_error({options.out_dir, 0, 0, why}, err);
  SimOptions o = options;
  o.duration_s = session_duration_s(options);
  if (o.unit_accel_errors) {
    Rng unit_rng(o.seed, RngStream::UnitAccelErrors);
    draw_unit_accel_errors(unit_rng, o.effects);
  }
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (ec) return writer_error({o.out_dir, 0, 0, "cannot create the output folder: " + ec.message()}, err);
  const dataset::DatasetPaths paths{o.out_dir};
  const bool flight = o.mode == SimMode::Flight;

  Rng traj_rng(o.seed, RngStream::Trajectory), param_rng(o.seed, RngStream::ImuErrorParameters);
  Rng noise_rng(o.seed, RngStream::ImuNoise), env_rng(o.seed, RngStream::Environment);
  const ImuErrorModel model = o.error_model ? *o.error_model : draw_default_imu_error_model(param_rng);
  Site site = draw_site(traj_rng);
  if (o.site_lat_lon_h) {
    site.lat_rad = (*o.site_lat_lon_h)[0] * kDegToRad;
    site.lon_rad = (*o.site_lat_lon_h)[1] * kDegToRad;
    site.ground_h_m = (*o.site_lat_lon_h)[2];
  }
  // Board clock at the first sample: not zero (dataset-format.md), whole milliseconds.
  const double t0 = std::round(traj_rng.uniform(100.0, 5000.0) * 1000.0) / 1000.0;
  const TemperatureProfile temp = flight ? draw_flight_temperature(env_rng) : draw_bench_temperature(env_rng);
  Eigen::Vector3d earth_field = earth_field_n_uT(site.lat_rad, site.lon_rad, site.ground_h_m, kBenchDecimalYear);

  const double dt = 1.0 / o.imu_rate_hz;
  const auto substeps = static_cast<std::uint64_t>(std::ceil(o.min_internal_rate_hz / o.imu_rate_hz));
  const auto n_imu = static_cast<std::uint64_t>(std::floor(o.duration_s * o.imu_rate_hz));
  // A flight's field is that of its date, set once its clock is drawn below.
  ImuSensor imu(model, o.effects, earth_field, dt, noise_rng);

  dataset::CsvWriter imu_out(dataset::kImuSchema), truth_out(dataset::kTruthSchema);
  dataset::set_imu_formats(imu_out);
  dataset::set_truth_formats(truth_out);
  dataset::NmeaLogWriter gps_out;
  if (!imu_out.open(paths.imu())) return writer_error(imu_out.error(), err);
  if (flight && !truth_out.open(paths.truth())) return writer_error(truth_out.error(), err);
  if (flight && !gps_out.open(paths.gps())) return writer_error(gps_out.error(), err);

  dataset::CsvRow row;
  if (flight) {
    Trajectory traj(site, t0, t0 + o.duration_s, dt / static_cast<double>(substeps), traj_rng, o.airframe);
    const double fix_period = 1.0 / o.gps_rate_hz;
    UtcClock clock;
    clock.utc_minus_board_s = std::floor(traj_rng.uniform(2.0, 16.0) * 3600.0) - t0;
    clock.year = 2024 + static_cast<int>(traj_rng.below(3));
    clock.month = 1 + static_cast<int>(traj_rng.below(12));
    clock.day = 1 + static_cast<int>(traj_rng.below(28));
    earth_field = earth_field_n_uT(site.lat_rad, site.lon_rad, site.ground_h_m,
                                   est::geomag::decimal_year(clock.year, clock.month, clock.day,
                                                             std::fmod(t0 + clock.utc_minus_board_s, 86400.0)));
    imu.set_earth_field(earth_field);
    GpsReceiver gps(o.gps, o.effects, clock, fix_period, o.seed);
    std::uint64_t fix_index = 1;
    // The fix stamped t_e measures the antenna at t_e - latency.
    auto next_sample = [&] { return t0 + static_cast<double>(fix_index) * fix_period - gps.latency_s(); };
    for (std::uint64_t k = 0; k < n_imu; ++k) {
      const double t = t0 + static_cast<double>(k) * dt;
      const TrueMotion m = traj.motion();
      gps.remember(m);
      fill_truth_row(row, m);
      if (!truth_out.write(row)) return writer_error(truth_out.error(), err);
      fill_imu_row(row, t, imu.sample(m.specific_force_b_m_s2, m.omega_ib_b_rad_s, m.C_nb, temp.at(t - t0)));
      if (!imu_out.write(row)) return writer_error(imu_out.error(), err);
      for (std::uint64_t s = 0; s < substeps; ++s) {
        const double t_next = traj.time() + dt / static_cast<double>(substeps);
        while (next_sample() < t_next) {
          const double ts = next_sample();
          if (ts >= traj.time()) {
            if (!gps.fix(traj.motion_at(ts), ts + gps.latency_s(), gps_out)) return writer_error(gps_out.error(), err);
          }
          ++fix_index;
        }
        traj.step();
      }
    }
    result.gps_sentences = gps.sentences();
    result.corrupted_sentences = gps.corrupted();
    result.hidden["site"] = site_json(site);
    result.hidden["utc"] = {{"utc_minus_board_s", clock.utc_minus_board_s},
                            {"date", fmt::format("{:04d}-{:02d}-{:02d}", clock.year, clock.month, clock.day)}};
    result.hidden["gps_error_model"] = gps_error_model_json(o.gps);
    result.hidden["gps_sentences"] = gps.sentences();
    result.hidden["corrupted_sentences"] = gps.corrupted();
  } else if (o.positions > 1) {
    // Held in N attitudes, turned between them: gravity and Earth rate are
    // constant in NED, the body turns under them.
    const NavState bench{site.heading_rad, site.lat_rad, site.lon_rad, site.ground_h_m};
    const TrueMotion level = evaluate_motion(t0, ControlValues{}, bench);
    const Eigen::Vector3d f_n = level.C_nb * level.specific_force_b_m_s2;
    const Eigen::Vector3d w_ie_n = level.C_nb * level.omega_ib_b_rad_s;
    Rng positions_rng(o.seed, RngStream::BenchPositions);
    const BenchSchedule schedule(o.positions, hold_of(o), o.transition_s, site.heading_rad, positions_rng);
    Eigen::Matrix3d C_nb;
    Eigen::Vector3d w_nb_b;
    for (std::uint64_t k = 0; k < n_imu; ++k) {
      const double tau = static_cast<double>(k) * dt;
      schedule.at(tau, C_nb, w_nb_b);
      const Eigen::Vector3d f_b = C_nb.transpose() * f_n, w_b = w_nb_b + C_nb.transpose() * w_ie_n;
      fill_imu_row(row, t0 + tau, imu.sample(f_b, w_b, C_nb, temp.at(tau)));
      if (!imu_out.write(row)) return writer_error(imu_out.error(), err);
    }
    result.hidden["site"] = site_json(site);
    result.hidden["hold_s"] = hold_of(o);
    result.hidden["transition_s"] = o.transition_s;
    nlohmann::json positions = nlohmann::json::array();
    for (const BenchPosition& p : schedule.positions()) {
      positions.push_back({{"name", calibration::position_name(p.index)},
                           {"up_b", vec_json(calibration::position_up_b(p.index))},
                           {"still_from_t", t0 + p.still_from_s},
                           {"still_to_t", t0 + p.still_to_s},
                           {"true_specific_force_b_m_s2", vec_json(p.C_nb.transpose() * f_n)},
                           {"true_angular_rate_b_rad_s", vec_json(p.C_nb.transpose() * w_ie_n)}});
    }
    result.hidden["positions"] = positions;
  } else {
    // Level and still on a bench: one constant true motion.
    const NavState bench{site.heading_rad, site.lat_rad, site.lon_rad, site.ground_h_m};
    const TrueMotion m = evaluate_motion(t0, ControlValues{}, bench);
    for (std::uint64_t k = 0; k < n_imu; ++k) {
      const double t = t0 + static_cast<double>(k) * dt;
      fill_imu_row(row, t, imu.sample(m.specific_force_b_m_s2, m.omega_ib_b_rad_s, m.C_nb, temp.at(t - t0)));
      if (!imu_out.write(row)) return writer_error(imu_out.error(), err);
    }
    result.hidden["site"] = site_json(site);
    result.hidden["true_specific_force_b_m_s2"] = {m.specific_force_b_m_s2.x(), m.specific_force_b_m_s2.y(),
                                                   m.specific_force_b_m_s2.z()};
    result.hidden["true_angular_rate_b_rad_s"] = {m.omega_ib_b_rad_s.x(), m.omega_ib_b_rad_s.y(),
                                                  m.omega_ib_b_rad_s.z()};
  }
  if (!imu_out.close()) return writer_error(imu_out.error(), err);
  if (flight && !truth_out.close()) return writer_error(truth_out.error(), err);
  if (flight && !gps_out.close()) return writer_error(gps_out.error(), err);
  result.imu_rows = n_imu;

  dataset::Meta meta;
  meta.imu_rate_hz = o.imu_rate_hz;
  if (flight) meta.gps_rate_hz = o.gps_rate_hz;
  if (o.positions > 1)
    meta.object["notes"] = fmt::format("sinu simulate static --seed {} --positions {}", o.seed, o.positions);
  else if (flight && o.airframe != Airframe::FixedWing)
    meta.object["notes"] =
        fmt::format("sinu simulate flight --seed {} --airframe {}", o.seed, airframe_name(o.airframe));
  else
    meta.object["notes"] = fmt::format("sinu simulate {} --seed {}", flight ? "flight" : "static", o.seed);
  if (!dataset::write_meta(paths.meta(), meta, err)) return false;

  nlohmann::json& h = result.hidden;
  h["schema"] = "sinu-simulate-hidden/1";
  h["mode"] = flight ? "flight" : "static";
  h["seed"] = o.seed;
  h["imu_rate_hz"] = o.imu_rate_hz;
  if (flight) h["gps_rate_hz"] = o.gps_rate_hz;
  if (flight) h["airframe"] = airframe_name(o.airframe);
  h["t0_s"] = t0;
  h["duration_s"] = o.duration_s;
  h["imu_error_model"] = imu_error_model_json(model);
  h["temperature"] = temperature_json(temp);
  h["earth_field_ned_uT"] = {earth_field.x(), earth_field.y(), earth_field.z()};
  h["temp_bias_reference_degC"] = kTempBiasReference_degC;
  h["effects"] = effects_to_json(o.effects);
  return true;
}

}  // namespace sinu::sim
