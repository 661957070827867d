#include "firmware/host/calibration/report.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <cmath>
#include <filesystem>

#include "estimator/noise/ar_model.hpp"

namespace sinu::calibration {

namespace {

// Autocorrelation rows: every lag for the first 20 s (the AR and filter
// structure), then every 10th lag (keeps a 600 s curve to a few thousand rows).
constexpr double kFullResolution_s = 20.0;
constexpr std::size_t kDecimation = 10;

/// The chosen model (method, order) among `fits`, or null.
const noise::ArModel* chosen_model(const std::array<std::vector<noise::ArModel>, kArMethods>& fits, const ModelChoice& m) {
  return fits[m.method].size() >= m.order ? &fits[m.method][m.order - 1] : nullptr;
}

/// The autocorrelation of an AR model sampled every `period_s`, at any lag (linear between its lags).
struct RateAcf {
  std::vector<double> r;
  double period_s = 0.0;
  double at(double lag_s) const {
    if (r.empty()) return NAN;
    const double x = lag_s / period_s;
    const auto k = static_cast<std::size_t>(x);
    if (k + 1 >= r.size()) return r.back();
    return r[k] + (x - static_cast<double>(k)) * (r[k + 1] - r[k]);
  }
};

void write_acf(const std::string& path, const AxisCalibration& a, double dt, const RateAcf& at_rate) {
  auto out = fmt::output_file(path);
  out.print("lag_s,measured,gm1,ar_model_rate");
  std::array<std::vector<double>, kArMethods> model_acf;
  const std::size_t max_lag = a.acf.empty() ? 0 : a.acf.size() - 1;
  for (std::size_t m = 0; m < kArMethods; ++m) {
    out.print(",{}_ar{}", kArMethodNames[m], a.model.order);
    if (a.ar[m].size() >= a.model.order) model_acf[m] = noise::ar_autocorrelation(a.ar[m][a.model.order - 1], max_lag);
  }
  out.print("\n");
  const auto full = static_cast<std::size_t>(kFullResolution_s / dt);
  for (std::size_t k = 0; k <= max_lag && !a.acf.empty(); k += (k < full ? 1 : kDecimation)) {
    const double lag = static_cast<double>(k) * dt;
    out.print("{:.6g},{:.9g},{:.9g},{:.9g}", lag, a.acf[k], a.gm.autocorrelation(lag), at_rate.at(lag));
    for (const auto& r : model_acf) {
      if (r.empty()) out.print(",");
      else out.print(",{:.9g}", r[k]);
    }
    out.print("\n");
  }
}

void write_allan(const std::string& path, const AxisCalibration& a) {
  auto out = fmt::output_file(path);
  out.print("tau_s,adev,adev_low,adev_high,model_adev\n");
  for (const auto& p : a.allan) {
    out.print("{:.6g},{:.9g},{:.9g},{:.9g},{:.9g}\n", p.tau_s, p.adev, p.adev_low, p.adev_high,
              a.terms.model_adev(p.tau_s));
  }
}

/// The Allan deviation measured and what each model predicts (white noise N added), every measured tau.
void write_allan_models(const std::string& path, const AxisAtRate& a) {
  auto out = fmt::output_file(path);
  out.print("tau_s,measured,gm1,ar_imu_rate,ar_model_rate\n");
  for (std::size_t k = 0; k < a.tau_s.size(); ++k)
    out.print("{:.6g},{:.9g},{:.9g},{:.9g},{:.9g}\n", a.tau_s[k], a.adev_measured[k], a.adev_gm[k], a.adev_ar_imu[k],
              a.adev_ar_model[k]);
}

/// report.md's section on the model rate: the candidates' scores and, per axis, the
/// Allan deviation measured and predicted at a few averaging times.
template <class Out>
void print_model_rate(Out& md, const SessionCalibration& ses) {
  const ModelRate& r = ses.model_rate;
  md.print("### AR at the model rate\n\nThe AR models are also fitted to block means of the denoised series at "
           "slower rates; the rate whose {} AR({}) predicts the measured Allan deviation best over 1-100 s (the "
           "span of an outage; RMS of ln(model / measured), white noise N added) is written to calib.json "
           "(`ar_model_rate`) and used by the EKF unless `--ar-rate imu`.\n\n| rate [Hz] | score |\n|---|---|\n",
           kArMethodNames[ses.axes[0].model.method], ses.axes[0].model.order);
  for (const RateScore& c : r.candidates)
    md.print("| {:.3g}{} | {:.3f} |\n", c.rate_hz, c.rate_hz == r.rate_hz ? " (chosen)" : "", c.score);
  md.print("\nAllan deviation, measured / GM1 / AR at {:.3g} Hz / AR at {:.3g} Hz (model rate), white noise N "
           "added to each model (allan_models_s<n>_<axis>.csv has every tau):\n\n| axis |",
           ses.sample_rate_hz, r.rate_hz);
  const double taus[] = {1.0, 3.0, 10.0, 30.0, 100.0};
  for (const double t : taus) md.print(" tau {:.0f} s |", t);
  md.print("\n|---|---|---|---|---|---|\n");
  for (std::size_t i = 0; i < ses.axes.size(); ++i) {
    const AxisAtRate& a = r.axes[i];
    md.print("| {} |", ses.axes[i].axis);
    for (const double t : taus) {
      std::size_t best = a.tau_s.size();
      for (std::size_t k = 0; k < a.tau_s.size(); ++k)
        if (best == a.tau_s.size() || std::abs(std::log(a.tau_s[k] / t)) < std::abs(std::log(a.tau_s[best] / t))) best = k;
      if (best == a.tau_s.size()) md.print(" |");
      else md.print(" {:.3g} / {:.3g} / {:.3g} / {:.3g} |", a.adev_measured[best], a.adev_gm[best], a.adev_ar_imu[best],
                    a.adev_ar_model[best]);
    }
    md.print("\n");
  }
  md.print("\n");
}

}  // namespace

bool write_report(const CalibrationRun& run, const std::string& dir, std::string& why) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    why = dir + ": cannot create report folder: " + ec.message();
    return false;
  }
  try {
    const auto path = [&](const std::string& name) { return (fs::path(dir) / name).string(); };
    auto variance = fmt::output_file(path("ar_variance.csv"));
    auto coeffs = fmt::output_file(path("ar_coefficients.csv"));
    auto gm_ar = fmt::output_file(path("gm_vs_ar.csv"));
    auto terms = fmt::output_file(path("allan_terms.csv"));
    auto md = fmt::output_file(path("report.md"));
    variance.print("session,axis,method,order,variance\n");
    coeffs.print("session,axis,method,order,index,value\n");
    gm_ar.print("session,axis,gm_tau_s,gm_variance,gm_driving_variance,gm_prediction_variance");
    for (const char* m : kArMethodNames) gm_ar.print(",{}_ar3", m);
    gm_ar.print("\n");
    terms.print("session,axis,N,B,K,Q,R,B_tau_s,B_floor_reached\n");
    md.print("# Calibration report\n\nDenoiser: {}.\n\n", run.denoiser.name);
    for (std::size_t s = 0; s < run.sessions.size(); ++s) {
      const SessionCalibration& ses = run.sessions[s];
      const double dt = 1.0 / ses.sample_rate_hz;
      md.print("## Session {}: {}\n\n{:.0f} s at {:.3f} Hz, {} rows ({} without IMU values skipped, {} gaps).\n\n", s + 1,
               ses.dataset, ses.duration_s, ses.sample_rate_hz, ses.rows, ses.rows_without_imu, ses.gaps);
      md.print("| axis | turn-on bias | N | B (at tau) | K | GM1 tau_s | model |\n|---|---|---|---|---|---|---|\n");
      std::vector<std::string> all_findings;
      for (const AxisCalibration& a : ses.axes) {
        RateAcf at_rate;
        if (ses.model_rate.valid()) {
          const std::size_t i = static_cast<std::size_t>(&a - ses.axes.data());
          at_rate.period_s = 1.0 / ses.model_rate.rate_hz;
          if (const noise::ArModel* m = chosen_model(ses.model_rate.axes[i].ar, a.model)) {
            const double max_lag_s = a.acf.empty() ? 0.0 : static_cast<double>(a.acf.size()) * dt;
            // Autocovariance of the block means: at lags beyond a block it is the process's own.
            at_rate.r = noise::ar_autocorrelation(*m, static_cast<std::size_t>(max_lag_s / at_rate.period_s) + 2);
          }
          write_allan_models(path(fmt::format("allan_models_s{}_{}.csv", s + 1, a.axis)), ses.model_rate.axes[i]);
        }
        write_acf(path(fmt::format("acf_s{}_{}.csv", s + 1, a.axis)), a, dt, at_rate);
        write_allan(path(fmt::format("allan_s{}_{}.csv", s + 1, a.axis)), a);
        for (std::size_t m = 0; m < kArMethods; ++m) {
          for (const auto& model : a.ar[m]) {
            variance.print("{},{},{},{},{:.12g}\n", s + 1, a.axis, kArMethodNames[m], model.order(), model.variance);
            for (std::size_t i = 1; i < model.a.size(); ++i) {
              coeffs.print("{},{},{},{},{},{:.12g}\n", s + 1, a.axis, kArMethodNames[m], model.order(), i, model.a[i]);
            }
          }
        }
        gm_ar.print("{},{},{:.9g},{:.9g},{:.9g},{:.9g}", s + 1, a.axis, a.gm.tau_s, a.gm.variance,
                    a.gm.driving_variance(dt), a.gm_prediction_variance);
        for (const auto& models : a.ar) {
          if (models.size() >= 3) gm_ar.print(",{:.9g}", models[2].variance);
          else gm_ar.print(",");
        }
        gm_ar.print("\n");
        terms.print("{},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g},{:.6g},{}\n", s + 1, a.axis, a.terms.N, a.terms.B,
                    a.terms.K, a.terms.Q, a.terms.R, a.terms.B_tau_s, a.terms.floor_reached ? 1 : 0);
        md.print("| {} | {:.6g} | {:.3g} | {:.3g} ({:.3g} s) | {:.3g} | {:.3g} | {} AR({}) |\n", a.axis, a.turn_on_bias,
                 a.terms.N, a.terms.B, a.terms.B_tau_s, a.terms.K, a.gm.tau_s, kArMethodNames[a.model.method],
                 a.model.order);
        for (auto& f : findings(a, dt)) all_findings.push_back(std::move(f));
      }
      md.print("\nMagnetometer: ");
      for (std::size_t i = 0; i < kMagAxes.size(); ++i) {
        md.print("{} mean {:.3f} uT std {:.3f} uT ({} samples){}", kMagAxes[i], ses.mag[i].mean_uT, ses.mag[i].std_uT,
                 ses.mag[i].samples, i + 1 < kMagAxes.size() ? "; " : ".\n\n");
      }
      if (ses.model_rate.valid()) print_model_rate(md, ses);
      md.print("### Where the models fail\n\n");
      if (all_findings.empty()) md.print("No misfit above the report's thresholds.\n");
      for (const auto& f : all_findings) md.print("- {}\n", f);
      md.print("\nPlots (tools/plot_calibration.py): acf_s{0}_<axis>.png, allan_s{0}_<axis>.png\n\n", s + 1);
    }
  } catch (const std::exception& e) {  // fmt::output_file throws std::system_error on I/O failure
    why = dir + ": " + e.what();
    return false;
  }
  return true;
}

}  // namespace sinu::calibration
