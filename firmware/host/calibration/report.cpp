#include "firmware/host/calibration/report.hpp"

#include <fmt/format.h>
#include <fmt/os.h>

#include <filesystem>

#include "estimator/noise/ar_model.hpp"

namespace sinu::calibration {

namespace {

// Autocorrelation rows: every lag for the first 20 s (the AR and filter
// structure), then every 10th lag (keeps a 600 s curve to a few thousand rows).
constexpr double kFullResolution_s = 20.0;
constexpr std::size_t kDecimation = 10;

void write_acf(const std::string& path, const AxisCalibration& a, double dt) {
  auto out = fmt::output_file(path);
  out.print("lag_s,measured,gm1");
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
    out.print("{:.6g},{:.9g},{:.9g}", lag, a.acf[k], a.gm.autocorrelation(lag));
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
        write_acf(path(fmt::format("acf_s{}_{}.csv", s + 1, a.axis)), a, dt);
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
