#include "firmware/host/calibration/calib_json.hpp"

#include <cmath>
#include <fstream>

#include "firmware/host/calibration/six_position_run.hpp"

namespace sinu::calibration {

namespace {

using nlohmann::json;

json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json ar_json(const noise::ArModel& m) {
  return json{{"a", m.a}, {"variance", m.variance}, {"stable", noise::ar_is_stable(m)}};
}

json axis_json(const AxisCalibration& a, double dt) {
  json j;
  j["unit"] = a.axis[0] == 'a' ? "m/s^2" : "rad/s";
  j["samples"] = a.samples;
  j["turn_on_bias"] = a.turn_on_bias;
  j["raw_std"] = a.raw_std;
  j["denoised_std"] = a.denoised_std;
  j["gm"] = {{"tau_s", number_or_null(a.gm.tau_s)},
             {"variance", a.gm.variance},
             {"driving_variance", a.gm.driving_variance(dt)},
             {"prediction_variance", a.gm_prediction_variance},
             {"method", "1/e crossing of the biased autocorrelation"},
             {"decays", a.gm.crossed}};
  json ar = json::object();
  json sel = json::object();
  for (std::size_t m = 0; m < kArMethods; ++m) {
    json list = json::array();
    for (const auto& model : a.ar[m]) list.push_back(ar_json(model));
    ar[kArMethodNames[m]] = list;
    sel[kArMethodNames[m]] = {{"fpe", a.selected[m].fpe}, {"aic", a.selected[m].aic}, {"bic", a.selected[m].bic}};
  }
  j["ar"] = ar;
  j["order_selection"] = sel;
  json allan;
  std::vector<double> tau, adev, lo, hi;
  for (const auto& p : a.allan) {
    tau.push_back(p.tau_s);
    adev.push_back(p.adev);
    lo.push_back(p.adev_low);
    hi.push_back(p.adev_high);
  }
  allan["tau_s"] = tau;
  allan["adev"] = adev;
  allan["adev_low"] = lo;
  allan["adev_high"] = hi;
  allan["N"] = a.terms.N;
  allan["B"] = a.terms.B;
  allan["K"] = a.terms.K;
  allan["Q"] = a.terms.Q;
  allan["R"] = a.terms.R;
  allan["B_tau_s"] = a.terms.B_tau_s;
  allan["B_fit"] = a.terms.B_fit;
  allan["B_floor_reached"] = a.terms.floor_reached;
  j["allan"] = allan;
  json model = {{"kind", "ar"}, {"method", kArMethodNames[a.model.method]}, {"order", a.model.order}};
  const auto& chosen = a.ar[a.model.method];
  if (chosen.size() >= a.model.order) {
    model["a"] = chosen[a.model.order - 1].a;
    model["variance"] = chosen[a.model.order - 1].variance;
  }
  j["model"] = model;
  return j;
}

/// The AR models at the chosen model rate, the scores of every candidate rate,
/// and per axis the Allan deviation measured and predicted (model_rate.hpp).
json model_rate_json(const ModelRate& r) {
  json j;
  j["rate_hz"] = r.rate_hz;
  j["decimation"] = r.decimation;
  j["criterion"] = "RMS of ln(ADEV of the model + white noise N / ADEV measured) over 1-100 s, all axes";
  json scores = json::array();
  for (const RateScore& c : r.candidates)
    scores.push_back({{"rate_hz", c.rate_hz}, {"decimation", c.decimation}, {"score", number_or_null(c.score)}});
  j["candidates"] = scores;
  for (std::size_t i = 0; i < kImuAxes.size(); ++i) {
    const AxisAtRate& a = r.axes[i];
    json ax;
    for (std::size_t m = 0; m < kArMethods; ++m) {
      json list = json::array();
      for (const auto& model : a.ar[m]) list.push_back(ar_json(model));
      ax["ar"][kArMethodNames[m]] = list;
    }
    ax["adev"] = {{"tau_s", a.tau_s},         {"measured", a.adev_measured}, {"gm", a.adev_gm},
                  {"ar_imu_rate", a.adev_ar_imu}, {"ar_model_rate", a.adev_ar_model}};
    j["axes"][kImuAxes[i]] = ax;
  }
  return j;
}

json session_json(const SessionCalibration& s) {
  json j;
  j["dataset"] = s.dataset;
  j["sample_rate_hz"] = s.sample_rate_hz;
  j["duration_s"] = s.duration_s;
  j["rows"] = s.rows;
  j["rows_without_imu_skipped"] = s.rows_without_imu;
  j["gaps"] = s.gaps;
  const double dt = 1.0 / s.sample_rate_hz;
  for (const auto& a : s.axes) j["axes"][a.axis] = axis_json(a, dt);
  if (s.model_rate.valid()) j["ar_model_rate"] = model_rate_json(s.model_rate);
  for (std::size_t i = 0; i < kMagAxes.size(); ++i) {
    j["magnetometer"][kMagAxes[i]] = {
        {"mean_uT", s.mag[i].mean_uT}, {"std_uT", s.mag[i].std_uT}, {"samples", s.mag[i].samples}};
  }
  return j;
}

}  // namespace

nlohmann::json calibration_to_json(const CalibrationRun& run) {
  json j;
  j["format"] = "sinu-calib";
  j["version"] = 1;
  const SessionCalibration& first = run.sessions.front();
  j["denoiser"] = {{"name", run.denoiser.name},
                   {"wavelet", run.denoiser.wavelet.empty() ? json(nullptr) : json(run.denoiser.wavelet)},
                   {"levels", run.denoiser.levels},
                   {"sample_rate_hz", first.sample_rate_hz}};
  if (!first.detail_sigma[0].empty()) {
    // The flight keeps a detail beyond keep_details_above_sigma of these (fast motion).
    j["denoiser"]["keep_details_above_sigma"] = kKeepDetailsAboveSigma;
    for (std::size_t i = 0; i < kImuAxes.size(); ++i) j["denoiser"]["detail_sigma"][kImuAxes[i]] = first.detail_sigma[i];
  }
  json s0 = session_json(first);
  j["dataset"] = first.dataset;
  j["sample_rate_hz"] = first.sample_rate_hz;
  j["axes"] = s0["axes"];
  if (s0.contains("ar_model_rate")) j["ar_model_rate"] = s0["ar_model_rate"];
  j["magnetometer"] = s0["magnetometer"];
  j["sessions"] = json::array();
  for (const auto& s : run.sessions) j["sessions"].push_back(session_json(s));
  if (run.six_position) j["six_position"] = six_position_json(*run.six_position);
  return j;
}

bool write_calib_json(const CalibrationRun& run, const std::string& path, std::string& why) {
  std::ofstream out(path);
  if (!out) {
    why = path + ": cannot create file";
    return false;
  }
  out << calibration_to_json(run).dump(1) << '\n';
  out.close();
  if (!out) {
    why = path + ": write failed";
    return false;
  }
  return true;
}

}  // namespace sinu::calibration
