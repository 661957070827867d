#include "firmware/host/calibration/six_position_run.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "firmware/host/calibration/bench_positions.hpp"

namespace sinu::calibration {

namespace {

using nlohmann::json;

constexpr double kRadToDeg = 180.0 / std::numbers::pi;

json vec(const Eigen::Vector3d& v) { return json::array({v.x(), v.y(), v.z()}); }
json mat(const Eigen::Matrix3d& m) {
  json rows = json::array();
  for (Eigen::Index r = 0; r < 3; ++r) rows.push_back(vec(m.row(r).transpose()));
  return rows;
}

}  // namespace

SessionStillParts find_still_parts(const StaticSession& session, std::size_t input,
                                   const StillDetectorConfig& detector) {
  SessionStillParts p;
  p.segments = find_still_segments(session, input, detector);
  p.attitudes = count_attitudes(p.segments);
  p.noise_end = session.imu[0].size();
  if (p.attitudes >= 2) {
    // Noise models need one attitude held still: the longest hold (a series
    // joined from several would jump where gravity moves between axes).
    const auto longest = std::max_element(p.segments.begin(), p.segments.end(), [](const auto& a, const auto& b) {
      return a.end - a.begin < b.end - b.begin;
    });
    p.noise_begin = longest->begin;
    p.noise_end = longest->end;
    p.whole = false;
  }
  return p;
}

double mean_sigma_from_allan(const AxisCalibration& axis, double duration_s) {
  const auto& a = axis.allan;
  if (a.empty() || !(duration_s > 0.0)) return 1e-3;
  if (duration_s <= a.front().tau_s) return a.front().adev * std::sqrt(a.front().tau_s / duration_s);
  if (duration_s >= a.back().tau_s) return a.back().adev;
  std::size_t k = 1;
  while (a[k].tau_s < duration_s) ++k;
  const double x = std::log(duration_s / a[k - 1].tau_s) / std::log(a[k].tau_s / a[k - 1].tau_s);
  return std::exp((1.0 - x) * std::log(a[k - 1].adev) + x * std::log(a[k].adev));
}

PositionsOutcome calibrate_positions(const std::vector<SessionStillParts>& parts,
                                     const std::vector<SessionCalibration>& sessions, const GravityModel& gravity,
                                     SixPositionCalibration& out, std::string& why) {
  out = SixPositionCalibration{};
  std::vector<StillSegment> all;
  for (const SessionStillParts& p : parts) all.insert(all.end(), p.segments.begin(), p.segments.end());
  std::vector<std::size_t> group;
  const std::size_t attitudes = count_attitudes(all, &group);
  if (attitudes <= 1) return PositionsOutcome::SinglePosition;
  if (attitudes < kFaces) {
    std::vector<Eigen::Vector3d> seen;
    std::string have, missing;
    for (std::size_t k = 0; k < all.size(); ++k) {
      if (std::find(group.begin(), group.begin() + static_cast<std::ptrdiff_t>(k), group[k]) !=
          group.begin() + static_cast<std::ptrdiff_t>(k))
        continue;
      have += (have.empty() ? "" : ", ") + attitude_name(all[k].up_b());
      seen.push_back(all[k].up_b());
    }
    for (std::size_t f = 0; f < kFaces; ++f) {
      const bool held = std::any_of(seen.begin(), seen.end(), [&](const Eigen::Vector3d& u) {
        return u.dot(position_up_b(f)) >= std::cos(kSameAttitude_rad);
      });
      if (!held) missing += (missing.empty() ? "" : ", ") + position_name(f);
    }
    why = fmt::format("the session was held still in {} attitudes ({}): too few faces for a multi-position "
                      "calibration, which needs at least 6 (the six faces +-x, +-y, +-z up{}{}); a noise calibration "
                      "needs the board still in one attitude throughout",
                      attitudes, have, missing.empty() ? "" : "; missing: ", missing);
    return PositionsOutcome::Failed;
  }
  out.gravity = gravity;
  out.attitudes = attitudes;
  out.segments = all;
  for (const SessionCalibration& s : sessions) out.datasets.push_back(s.dataset);
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const SessionCalibration& s = sessions[i];
    SixPositionCalibration::Span span;
    span.whole = parts[i].whole;
    if (!span.whole) {
      const auto longest = std::max_element(parts[i].segments.begin(), parts[i].segments.end(),
                                            [](const auto& a, const auto& b) { return a.end - a.begin < b.end - b.begin; });
      span.t_start_s = longest->t_start_s;
      span.t_end_s = longest->t_end_s;
    } else {
      span.t_end_s = s.duration_s;  // relative: the whole session
    }
    out.noise_spans.push_back(span);
  }
  for (const StillSegment& seg : all) {
    SegmentMean m;
    m.accel_m_s2 = seg.accel_mean_m_s2;
    m.gyro_rad_s = seg.gyro_mean_rad_s;
    for (std::size_t a = 0; a < 3; ++a)
      m.accel_sigma_m_s2[static_cast<Eigen::Index>(a)] =
          mean_sigma_from_allan(sessions[seg.input].axes[a], seg.duration_s());
    out.means.push_back(m);
  }
  if (!fit_six_position(out.means, gravity, out.fit, why)) return PositionsOutcome::Failed;
  return PositionsOutcome::Fitted;
}

json six_position_json(const SixPositionCalibration& c) {
  const SixPositionFit& f = c.fit;
  json j;
  j["model"] = "m = (I + diag s)(I + M) f + b; |f| = g in every still segment";
  j["method"] = "weighted Levenberg-Marquardt from zero on the still segments' means; weights from the Allan "
                "deviation at the segment's length; covariance (J^T W J)^-1 x max(1, chi2/dof)";
  j["gravity_m_s2"] = f.gravity_m_s2;
  j["gravity_relative_sigma"] = f.gravity_relative_sigma;
  j["latitude_deg"] = c.gravity.latitude_deg;
  j["latitude_given"] = c.gravity.latitude_given;
  j["height_m"] = c.gravity.height_m;
  j["height_given"] = c.gravity.height_given;
  j["segments_used"] = f.segments;
  j["attitudes"] = c.attitudes;
  j["parameters"] = f.parameters;
  j["dof"] = f.dof;
  j["chi2_per_dof"] = f.dof > 0 ? json(f.chi2 / static_cast<double>(f.dof)) : json(nullptr);
  j["iterations"] = f.iterations;
  j["residual_rms_m_s2"] = f.residual_rms_m_s2;
  j["accel_bias"] = vec(f.accel_bias_m_s2);
  j["accel_bias_sigma"] = vec(f.accel_bias_sigma_m_s2);
  j["accel_scale"] = vec(f.accel_scale_ppm);
  j["accel_scale_sigma"] = vec(f.accel_scale_sigma_ppm);
  j["accel_misalign"] = mat(f.accel_misalign_rad);
  j["accel_misalign_sigma"] = mat(f.accel_misalign_sigma_rad);
  j["misalign_fitted"] = f.misalign_fitted;
  j["misalign_convention"] =
      "symmetric: M(i,j) = M(j,i); a rotation of the triad as a whole (M's antisymmetric part) is not observable "
      "from gravity";
  j["gyro_bias"] = vec(f.gyro_bias_rad_s);
  j["gyro_bias_sigma"] = vec(f.gyro_bias_sigma_rad_s);
  j["units"] = {{"accel_bias", "m/s^2"}, {"accel_scale", "ppm"}, {"accel_misalign", "rad"}, {"gyro_bias", "rad/s"}};
  j["use"] = "sinu replay, diagnose and fly: accel scale, misalignment and bias are applied as known corrections "
             "before the filter, whose accel_bias state keeps its prior (the change since this calibration); "
             "the gyro bias is not used (the alignment measures it at every start)";
  json segs = json::array();
  for (std::size_t k = 0; k < c.segments.size(); ++k) {
    const StillSegment& s = c.segments[k];
    segs.push_back({{"dataset", c.datasets[s.input]},
                    {"t_start", s.t_start_s},
                    {"t_end", s.t_end_s},
                    {"attitude", attitude_name(s.up_b())},
                    {"accel_mean_m_s2", vec(s.accel_mean_m_s2)},
                    {"accel_mean_sigma_m_s2", vec(c.means[k].accel_sigma_m_s2)},
                    {"gyro_mean_rad_s", vec(s.gyro_mean_rad_s)},
                    {"residual_m_s2", f.residuals_m_s2[k]}});
  }
  j["segments"] = segs;
  json spans = json::array();
  for (std::size_t i = 0; i < c.noise_spans.size(); ++i) {
    const auto& s = c.noise_spans[i];
    spans.push_back(s.whole ? json{{"dataset", c.datasets[i]}, {"span", "whole session"}}
                            : json{{"dataset", c.datasets[i]}, {"span", "longest still segment"},
                                   {"t_start", s.t_start_s}, {"t_end", s.t_end_s}});
  }
  j["noise_models_from"] = spans;
  return j;
}

std::string six_position_report(const SixPositionCalibration& c) {
  const SixPositionFit& f = c.fit;
  std::string attitudes;
  std::vector<std::size_t> group;
  count_attitudes(c.segments, &group);
  for (std::size_t k = 0; k < c.segments.size(); ++k)
    if (std::find(group.begin(), group.begin() + static_cast<std::ptrdiff_t>(k), group[k]) ==
        group.begin() + static_cast<std::ptrdiff_t>(k))
      attitudes += (attitudes.empty() ? "" : ", ") + attitude_name(c.segments[k].up_b());
  std::string s = fmt::format("six-position: {} still segments in {} attitudes ({})\n", f.segments, c.attitudes,
                              attitudes);
  const bool defaults = !c.gravity.latitude_given || !c.gravity.height_given;
  s += fmt::format("  gravity      {:.5f} m/s^2: normal gravity at {:.2f} deg, {:.0f} m{}\n", f.gravity_m_s2,
                   c.gravity.latitude_deg, c.gravity.height_m,
                   defaults ? fmt::format(" ({} not given: a common scale of +-{:.0f} ppm is in every scale's sigma; "
                                          "--latitude, --height)",
                                          !c.gravity.latitude_given ? (!c.gravity.height_given ? "latitude and height"
                                                                                              : "latitude")
                                                                    : "height",
                                          f.gravity_relative_sigma * 1e6)
                            : std::string());
  s += fmt::format("  accel bias   [{:9.5f} {:9.5f} {:9.5f}] +- [{:.5f} {:.5f} {:.5f}] m/s^2\n", f.accel_bias_m_s2.x(),
                   f.accel_bias_m_s2.y(), f.accel_bias_m_s2.z(), f.accel_bias_sigma_m_s2.x(),
                   f.accel_bias_sigma_m_s2.y(), f.accel_bias_sigma_m_s2.z());
  s += fmt::format("  accel scale  [{:9.0f} {:9.0f} {:9.0f}] +- [{:.0f} {:.0f} {:.0f}] ppm\n", f.accel_scale_ppm.x(),
                   f.accel_scale_ppm.y(), f.accel_scale_ppm.z(), f.accel_scale_sigma_ppm.x(),
                   f.accel_scale_sigma_ppm.y(), f.accel_scale_sigma_ppm.z());
  if (f.misalign_fitted) {
    const Eigen::Matrix3d& m = f.accel_misalign_rad;
    const Eigen::Matrix3d& e = f.accel_misalign_sigma_rad;
    s += fmt::format("  misalign     xy {:.3f} +- {:.3f}, xz {:.3f} +- {:.3f}, yz {:.3f} +- {:.3f} mrad (symmetric "
                     "part; the triad's rotation as a whole is not observable from gravity)\n",
                     1e3 * m(0, 1), 1e3 * e(0, 1), 1e3 * m(0, 2), 1e3 * e(0, 2), 1e3 * m(1, 2), 1e3 * e(1, 2));
  } else {
    s += "  misalign     not fitted: the faces sense it only at second order; tilted positions (--positions 14: "
         "the six faces and eight corners) make it observable\n";
  }
  s += fmt::format("  gyro bias    [{:9.5f} {:9.5f} {:9.5f}] +- [{:.5f} {:.5f} {:.5f}] deg/s (Earth rate's vertical "
                   "part removed; its horizontal part, direction unknown, is in the sigma)\n",
                   kRadToDeg * f.gyro_bias_rad_s.x(), kRadToDeg * f.gyro_bias_rad_s.y(),
                   kRadToDeg * f.gyro_bias_rad_s.z(), kRadToDeg * f.gyro_bias_sigma_rad_s.x(),
                   kRadToDeg * f.gyro_bias_sigma_rad_s.y(), kRadToDeg * f.gyro_bias_sigma_rad_s.z());
  s += fmt::format("  fit          {} unknowns, {} dof{}, residual rms {:.5f} m/s^2, {} iterations\n", f.parameters,
                   f.dof,
                   f.dof > 0 ? fmt::format(", chi2/dof {:.2f}", f.chi2 / static_cast<double>(f.dof)) : std::string(),
                   f.residual_rms_m_s2, f.iterations);
  for (std::size_t i = 0; i < c.noise_spans.size(); ++i) {
    const auto& sp = c.noise_spans[i];
    if (sp.whole)
      s += fmt::format("  noise models of {}: the whole session (one attitude)\n", c.datasets[i]);
    else
      s += fmt::format("  noise models of {}: its longest still segment, t {:.1f}..{:.1f} s ({:.0f} s)\n",
                       c.datasets[i], sp.t_start_s, sp.t_end_s, sp.t_end_s - sp.t_start_s);
  }
  return s;
}

}  // namespace sinu::calibration
