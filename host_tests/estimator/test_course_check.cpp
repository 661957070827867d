// A heading from the GNSS course is the heading only if the unit's x axis
// points along the track. Without a magnetometer, a unit mounted turned on
// a vehicle that starts gently (a car; the EKF's own heading barely moves
// under 0.4 m/s^2) was aligned that many degrees off and sure of it. The
// in-motion alignment checks the course after the alignment and the
// navigator turns the solution where they disagree (coarse_alignment.hpp).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "host_tests/estimator/navigator_run.hpp"

namespace sinu::test {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

struct TurnedRun {
  bool turned = false;
  double turn_deg = NAN;
  // Over the last 60 s: the attitude error against the unit's own attitude,
  // and its largest ratio to the filter's claimed heading sigma.
  double att_err_deg = NAN, worst_ratio = NAN;
};

/// The attitude error of every output against the truth, and the filter's heading sigma.
class HeadingScore final : public est::NavObserver {
 public:
  explicit HeadingScore(const std::vector<TruthSample>& truth) : truth_(truth) {}
  void on_nav(const est::NavOutput& o) override {
    const auto i = static_cast<std::size_t>(std::lround((o.nav.t_s - truth_.front().nav.t_s) * 40.0));
    if (i >= truth_.size()) return;
    t.push_back(o.nav.t_s);
    err_rad.push_back(attitude_error_rad(o.nav.q_nb, truth_[i].nav.q_nb));
    sigma_yaw_rad.push_back(std::sqrt(o.P_nav(8, 8)));
  }
  void on_innovation(const est::InnovationRecord&) override {}
  std::vector<double> t, err_rad, sigma_yaw_rad;

 private:
  const std::vector<TruthSample>& truth_;
};

/// The gentle flight with the unit mounted turned by `mount_deg` about its z
/// axis (its axes Rz(mount)^T of the vehicle's); perfect IMU without a
/// magnetometer, GNSS at 5 Hz.
TurnedRun run_turned(double mount_deg) {
  FlightProfile gentle;
  gentle.cruise_m_s = 8.0;  // 0.4 m/s^2 for 20 s, then gentle turns
  auto truth = AnalyticFlight(gentle).sample(40.0, 240.0);
  const auto gnss = AnalyticFlight::gnss(truth, 8, 0.05, Eigen::Vector3d::Zero(), 0.5, 0.1);
  const Eigen::Quaterniond mount(Eigen::AngleAxisd(mount_deg * kDeg, Eigen::Vector3d::UnitZ()));
  std::vector<est::ImuSample> imu;
  for (auto& s : truth) {
    imu.push_back(s.imu);
    imu.back().specific_force_b_m_s2 = mount.conjugate() * s.imu.specific_force_b_m_s2;
    imu.back().angular_rate_b_rad_s = mount.conjugate() * s.imu.angular_rate_b_rad_s;
    imu.back().has_mag = false;
    s.nav.q_nb = s.nav.q_nb * mount;  // the unit's attitude is what the filter must find
  }
  est::NavigatorConfig cfg;
  cfg.gps_latency_s = 0.05;  // as the epochs arrive
  HeadingScore score(truth);
  auto nav = std::make_unique<est::Navigator>();
  nav->init(cfg, &score, nullptr);
  feed(*nav, imu, gnss);
  TurnedRun r;
  EXPECT_TRUE(nav->aligned());
  EXPECT_EQ(nav->alignment_result().heading_source, est::HeadingSource::GnssCourse);
  r.turn_deg = nav->alignment_result().course_turn_rad / kDeg;
  r.turned = std::isfinite(r.turn_deg);
  double sum2 = 0.0, worst = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < score.t.size(); ++i) {
    if (score.t[i] < score.t.back() - 60.0) continue;
    sum2 += score.err_rad[i] * score.err_rad[i];
    worst = std::max(worst, score.err_rad[i] / score.sigma_yaw_rad[i]);
    ++n;
  }
  r.att_err_deg = std::sqrt(sum2 / static_cast<double>(n)) / kDeg;
  r.worst_ratio = worst;
  return r;
}

// The reference: mounted along the track, the course is the heading. What
// is left (1.75 deg over the last 60 s) is this flight's: without a
// magnetometer and under 0.4 m/s^2 the heading is frozen where the course
// put it (sigma 8.6 deg) until the turns.
TEST(CourseCheck, AUnitMountedAlongTheTrackKeepsItsCourseHeading) {
  const TurnedRun r = run_turned(0.0);
  std::printf("mounted along the track: attitude error over the last 60 s %.2f deg, at most %.2f heading sigmas\n",
              r.att_err_deg, r.worst_ratio);
  EXPECT_FALSE(r.turned) << r.turn_deg;
  EXPECT_LT(r.att_err_deg, 3.0);
  EXPECT_LT(r.worst_ratio, 3.0);
}

// Turned 90 or 180 deg the course was that far off and the EKF's heading,
// barely moved by 0.4 m/s^2, stayed with it (59 deg off under a 4-deg
// sigma). Checked, the solution is turned to the in-motion yaw (20-deg
// sigma, 3-6 deg off), and the filter restarts from its alignment.
// Measured over the last 60 s: 2.0 / 5.1 / 10.2 deg for +90 / -90 / 180,
// at most 0.4 / 0.9 / 1.8 of the filter's heading sigma (without a
// magnetometer the heading drifts between the accelerations that show it,
// 3 -> 15 deg here, and the sigma grows with it to 9). The bounds: honest
// (within three sigmas) and a heading, not the 60-180 deg left without the
// check (under 20 deg).
TEST(CourseCheck, AUnitMountedTurnedIsTurnedToItsOwnHeading) {
  for (const double mount : {90.0, -90.0, 180.0}) {
    const TurnedRun r = run_turned(mount);
    std::printf("mounted %+.0f deg: turned %.1f deg, attitude error over the last 60 s %.2f deg, at most %.2f heading "
                "sigmas\n", mount, r.turn_deg, r.att_err_deg, r.worst_ratio);
    EXPECT_TRUE(r.turned) << mount;
    EXPECT_LT(r.att_err_deg, 20.0) << mount;
    EXPECT_LT(r.worst_ratio, 3.0) << mount;
  }
}

}  // namespace
}  // namespace sinu::test
