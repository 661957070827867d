// MAVLink output: the message definitions against the official generated
// headers, the framing, and every field of HEARTBEAT, ODOMETRY and GPS_INPUT
// decoded by the independent reference (mavlink_reference.hpp) and compared
// with the NavSolution (units, frames, covariance layout).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>

#include "firmware/board/outputs/gps_time.hpp"
#include "firmware/board/outputs/mavlink_crc.hpp"
#include "firmware/board/outputs/mavlink_definitions.hpp"
#include "firmware/board/outputs/mavlink_frame.hpp"
#include "firmware/board/outputs/mavlink_messages.hpp"
#include "firmware/board/outputs/rate_schedule.hpp"
#include "host_tests/board/mavlink_reference.hpp"
#include "host_tests/board/nav_track.hpp"

namespace {

namespace mav = sinu::board::mavlink;
namespace ref = sinu::test::mavref;
using sinu::board::NavSolution;
using sinu::test::kDeg;

ref::Frame decode_one(const mav::MavlinkFrame& frame) {
  const ref::ParseResult r = ref::parse(frame.bytes());
  EXPECT_EQ(r.frames.size(), 1u);
  EXPECT_EQ(r.bad_crc + r.unknown_id + r.noise_bytes + r.incomplete_bytes, 0u);
  return r.frames.empty() ? ref::Frame{} : r.frames.front();
}

// ---- definitions ----------------------------------------------------------

void expect_published(const ref::XmlMessage& xml, const mav::MessageInfo& encoder, const ref::Published& pub) {
  SCOPED_TRACE(xml.name);
  // The test's own reading of the XML, the generator's way.
  EXPECT_EQ(xml.id, pub.id);
  EXPECT_EQ(ref::payload_length(xml, true), pub.length);
  EXPECT_EQ(ref::payload_length(xml, false), pub.min_length);
  EXPECT_EQ(ref::generator_crc_extra(xml), pub.crc_extra);  // proves the wire order of the base fields
  // The encoder's tables.
  EXPECT_EQ(encoder.id, pub.id);
  EXPECT_EQ(encoder.length, pub.length);
  EXPECT_EQ(encoder.base_length, pub.min_length);
  EXPECT_EQ(encoder.crc_extra, pub.crc_extra);
}

TEST(MavlinkDefinitions, IdsLengthsAndCrcExtraAsPublished) {
  expect_published(ref::heartbeat_xml(), mav::kHeartbeat, ref::kPublishedHeartbeat);
  expect_published(ref::gps_input_xml(), mav::kGpsInput, ref::kPublishedGpsInput);
  expect_published(ref::odometry_xml(), mav::kOdometry, ref::kPublishedOdometry);
}

TEST(MavlinkDefinitions, WireOffsetsAsPublished) {
  // Offsets from the MAVLINK_MESSAGE_INFO_x tables of the same headers
  // (c_library_v2 common/mavlink_msg_odometry.h, mavlink_msg_gps_input.h,
  // minimal/mavlink_msg_heartbeat.h); extensions are checked here only.
  const std::map<std::string, std::map<std::string, unsigned>> published = {
      {"HEARTBEAT", {{"custom_mode", 0}, {"type", 4}, {"autopilot", 5}, {"base_mode", 6}, {"system_status", 7},
                     {"mavlink_version", 8}}},
      {"GPS_INPUT", {{"time_usec", 0}, {"time_week_ms", 8}, {"lat", 12}, {"lon", 16}, {"alt", 20}, {"hdop", 24},
                     {"vdop", 28}, {"vn", 32}, {"ve", 36}, {"vd", 40}, {"speed_accuracy", 44},
                     {"horiz_accuracy", 48}, {"vert_accuracy", 52}, {"ignore_flags", 56}, {"time_week", 58},
                     {"gps_id", 60}, {"fix_type", 61}, {"satellites_visible", 62}, {"yaw", 63}}},
      {"ODOMETRY", {{"time_usec", 0}, {"x", 8}, {"y", 12}, {"z", 16}, {"q", 20}, {"vx", 36}, {"vy", 40},
                    {"vz", 44}, {"rollspeed", 48}, {"pitchspeed", 52}, {"yawspeed", 56}, {"pose_covariance", 60},
                    {"velocity_covariance", 144}, {"frame_id", 228}, {"child_frame_id", 229},
                    {"reset_counter", 230}, {"estimator_type", 231}, {"quality", 232}}}};
  for (const ref::XmlMessage* m : {&ref::heartbeat_xml(), &ref::gps_input_xml(), &ref::odometry_xml()}) {
    const auto& offsets = published.at(m->name);
    const auto layout = ref::wire_layout(*m);
    ASSERT_EQ(layout.size(), offsets.size()) << m->name;
    for (const ref::WireField& f : layout) EXPECT_EQ(f.offset, offsets.at(f.name)) << m->name << "." << f.name;
  }
}

TEST(MavlinkCrc, CheckValueOfBothImplementations) {
  const std::string text = "123456789";  // CRC-16/MCRF4XX check value 0x6F91
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  EXPECT_EQ(ref::crc_mcrf4xx(bytes), 0x6F91);
  EXPECT_EQ(mav::crc_accumulate(bytes, mav::kCrcSeed), 0x6F91);
}

// ---- framing --------------------------------------------------------------

TEST(MavlinkFrame, HeaderTruncationAndChecksum) {
  std::array<std::uint8_t, 9> payload{};  // a HEARTBEAT-sized payload of zeros
  mav::MavlinkFrame frame;
  ASSERT_EQ(mav::encode_frame(mav::kHeartbeat, payload, {7, 42, 191}, frame), 13u);  // 10 + 1 + 2
  EXPECT_EQ(frame.data[1], 1u) << "the first payload byte is never truncated";
  payload[3] = 0x5A;
  ASSERT_EQ(mav::encode_frame(mav::kHeartbeat, payload, {7, 42, 191}, frame), 16u);
  const ref::Frame f = decode_one(frame);
  EXPECT_EQ(frame.data[0], 0xFD);
  EXPECT_EQ(f.len, 4u);
  EXPECT_EQ(f.incompat, 0u);
  EXPECT_EQ(f.compat, 0u);
  EXPECT_EQ(f.seq, 7u);
  EXPECT_EQ(f.sysid, 42u);
  EXPECT_EQ(f.compid, 191u);
  EXPECT_EQ(f.msgid, 0u);
  EXPECT_EQ(f.payload.size(), 9u);
  EXPECT_EQ(f.payload[3], 0x5A);
  // A 24-bit id goes out low byte first; a wrong payload size is refused.
  std::array<std::uint8_t, 233> odometry_payload{};
  odometry_payload[0] = 1;
  ASSERT_GT(mav::encode_frame(mav::kOdometry, odometry_payload, {}, frame), 0u);
  EXPECT_EQ(frame.data[7], 331 & 0xFF);
  EXPECT_EQ(frame.data[8], 331 >> 8);
  EXPECT_EQ(frame.data[9], 0);
  EXPECT_EQ(mav::encode_frame(mav::kOdometry, payload, {}, frame), 0u);
  EXPECT_EQ(frame.size, 0u);
  // A flipped bit fails the reference's CRC check.
  ASSERT_GT(mav::encode_frame(mav::kHeartbeat, payload, {}, frame), 0u);
  frame.data[11] ^= 0x10;
  EXPECT_EQ(ref::parse(frame.bytes()).bad_crc, 1u);
}

// ---- HEARTBEAT -----------------------------------------------------------

TEST(MavlinkMessages, Heartbeat) {
  NavSolution s = sinu::test::sample_solution();
  mav::MavlinkFrame frame;
  ASSERT_GT(sinu::board::encode_heartbeat(s, {3, 1, 191}, frame), 0u);
  ref::Frame f = decode_one(frame);
  EXPECT_EQ(f.msgid, 0u);
  EXPECT_EQ(f.len, 9u);  // mavlink_version = 3 ends the payload: nothing to truncate
  EXPECT_EQ(f.f("type"), 18);           // MAV_TYPE_ONBOARD_CONTROLLER
  EXPECT_EQ(f.f("autopilot"), 8);       // MAV_AUTOPILOT_INVALID
  EXPECT_EQ(f.f("base_mode"), 0);
  EXPECT_EQ(f.f("custom_mode"), 0);
  EXPECT_EQ(f.f("system_status"), 4);   // MAV_STATE_ACTIVE
  EXPECT_EQ(f.f("mavlink_version"), 3);
  s.flags |= sinu::est::nav_flag::kLost;
  ASSERT_GT(sinu::board::encode_heartbeat(s, {}, frame), 0u);
  EXPECT_EQ(decode_one(frame).f("system_status"), 3);  // MAV_STATE_STANDBY
  s = NavSolution{};
  ASSERT_GT(sinu::board::encode_heartbeat(s, {}, frame), 0u);
  EXPECT_EQ(decode_one(frame).f("system_status"), 3);
}

// ---- ODOMETRY ------------------------------------------------------------

/// Euler angles (roll, pitch, yaw) from the rotation matrix (not the encoder's quaternion formulas).
Eigen::Vector3d euler_of(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d C = q.toRotationMatrix();
  return {std::atan2(C(2, 1), C(2, 2)), -std::asin(C(2, 0)), std::atan2(C(1, 0), C(0, 0))};
}

/// d(output error)/d(EKF error) by central differences. EKF errors: position
/// and velocity estimate - truth; attitude: truth = exp(phi) * estimate.
template <class Output>
Eigen::Matrix<double, 3, 9> numeric_jacobian(const NavSolution& s, Output output) {
  Eigen::Matrix<double, 3, 9> J;
  constexpr double h = 1e-6;
  for (int k = 0; k < 9; ++k) {
    Eigen::Matrix<double, 9, 1> dx = Eigen::Matrix<double, 9, 1>::Zero();
    dx(k) = h;
    // error = output(estimate) - output(truth(dx)), so d error / d dx = -d output(truth) / d dx
    J.col(k) = -(output(s, dx) - output(s, -dx)) / (2.0 * h);
  }
  return J;
}

Eigen::Quaterniond truth_attitude(const NavSolution& s, const Eigen::Matrix<double, 9, 1>& dx) {
  const Eigen::Vector3d phi = dx.segment<3>(6);
  const double angle = phi.norm();
  const Eigen::Quaterniond turn =
      angle > 0 ? Eigen::Quaterniond(Eigen::AngleAxisd(angle, phi / angle)) : Eigen::Quaterniond::Identity();
  return turn * s.q_nb;
}

Eigen::Matrix<double, 6, 6> unpack_upper(const std::vector<double>& v) {
  EXPECT_EQ(v.size(), 21u);
  Eigen::Matrix<double, 6, 6> M;
  std::size_t k = 0;
  for (int r = 0; r < 6; ++r)  // the definition: first six entries are the first row, next five the second, ...
    for (int c = r; c < 6; ++c) M(r, c) = M(c, r) = v.at(k++);
  return M;
}

void expect_close(const Eigen::MatrixXd& got, const Eigen::MatrixXd& want, double rel) {
  const double scale = want.cwiseAbs().maxCoeff();
  for (Eigen::Index r = 0; r < want.rows(); ++r)
    for (Eigen::Index c = 0; c < want.cols(); ++c)
      EXPECT_NEAR(got(r, c), want(r, c), rel * scale + 1e-6 * std::abs(want(r, c))) << "(" << r << "," << c << ")";
}

TEST(MavlinkMessages, OdometryFieldsFramesAndCovariance) {
  NavSolution origin = sinu::test::sample_solution();
  sinu::board::OdometryReference reference;
  reference.observe(origin);
  const Eigen::Vector3d d_ned(300.0, -200.0, -20.0);
  NavSolution s = origin;
  const Eigen::Vector3d llh = sinu::test::geodetic_at(origin.lat_deg, origin.lon_deg, origin.h_ellipsoid_m, d_ned);
  s.lat_deg = llh.x();
  s.lon_deg = llh.y();
  s.h_ellipsoid_m = llh.z();
  reference.observe(s);

  mav::MavlinkFrame frame;
  ASSERT_GT(sinu::board::encode_odometry(s, reference, {9, 1, 191}, frame), 0u);
  const ref::Frame f = decode_one(frame);
  EXPECT_EQ(f.msgid, 331u);
  EXPECT_EQ(f.len, 233u);  // quality ends the payload and is not 0
  EXPECT_EQ(f.f("time_usec"), 12'345'678);
  EXPECT_EQ(f.f("frame_id"), 1);         // MAV_FRAME_LOCAL_NED
  EXPECT_EQ(f.f("child_frame_id"), 12);  // MAV_FRAME_BODY_FRD
  // Position from the origin: the tangent plane within d^2/2R (1 cm here).
  EXPECT_NEAR(f.f("x"), d_ned.x(), 0.02);
  EXPECT_NEAR(f.f("y"), d_ned.y(), 0.02);
  EXPECT_NEAR(f.f("z"), d_ned.z(), 0.02);
  // q: w x y z of body FRD -> NED.
  const Eigen::Quaterniond q(f.a("q")[0], f.a("q")[1], f.a("q")[2], f.a("q")[3]);
  EXPECT_NEAR(q.angularDistance(s.q_nb), 0.0, 1e-6);
  EXPECT_NEAR((q * Eigen::Vector3d::UnitX() - s.q_nb * Eigen::Vector3d::UnitX()).norm(), 0.0, 1e-6);
  // Velocity in body axes, rotated back to NED it is the solution's.
  const Eigen::Vector3d v_b(f.f("vx"), f.f("vy"), f.f("vz"));
  EXPECT_NEAR((s.q_nb * v_b - s.v_ned_m_s).norm(), 0.0, 1e-5);
  EXPECT_NEAR(f.f("rollspeed"), 0.02, 1e-7);
  EXPECT_NEAR(f.f("pitchspeed"), -0.01, 1e-7);
  EXPECT_NEAR(f.f("yawspeed"), 0.15, 1e-7);

  // Pose covariance: (x y z roll pitch yaw), Euler errors by finite differences.
  Eigen::Matrix<double, 6, 9> Jp = Eigen::Matrix<double, 6, 9>::Zero();
  Jp.block<3, 3>(0, 0).setIdentity();
  Jp.bottomRows<3>() = numeric_jacobian(s, [](const NavSolution& n, const Eigen::Matrix<double, 9, 1>& dx) {
    return euler_of(truth_attitude(n, dx));
  });
  expect_close(unpack_upper(f.a("pose_covariance")), Jp * s.P_nav * Jp.transpose(), 1e-5);
  // Velocity covariance: the body velocity block; rates unknown (NaN).
  const auto Jv = numeric_jacobian(s, [](const NavSolution& n, const Eigen::Matrix<double, 9, 1>& dx) {
    const Eigen::Vector3d v_true = n.v_ned_m_s - dx.segment<3>(3);
    return Eigen::Vector3d(truth_attitude(n, dx).conjugate() * v_true);
  });
  const Eigen::Matrix<double, 6, 6> Pv = unpack_upper(f.a("velocity_covariance"));
  expect_close(Pv.topLeftCorner<3, 3>(), Jv * s.P_nav * Jv.transpose(), 1e-5);
  for (int r = 0; r < 6; ++r)
    for (int c = 3; c < 6; ++c) EXPECT_TRUE(std::isnan(Pv(r, c))) << r << "," << c;

  EXPECT_EQ(f.f("reset_counter"), 0);
  EXPECT_EQ(f.f("estimator_type"), 5);  // MAV_ESTIMATOR_TYPE_GPS_INS
  // quality = 100 s / (s + sigma_h), s = 5 m, sigma_h along the worst horizontal direction
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(s.P_nav.topLeftCorner<2, 2>());
  const double sigma_h = std::sqrt(eig.eigenvalues().maxCoeff());
  EXPECT_EQ(f.f("quality"), std::round(100.0 * 5.0 / (5.0 + sigma_h)));
}

TEST(MavlinkMessages, OdometryQualityResetCounterAndAlignment) {
  sinu::board::OdometryReference reference;
  mav::MavlinkFrame frame;
  NavSolution s = sinu::test::sample_solution();
  s.aligned = false;
  s.flags = 0;
  reference.observe(s);
  EXPECT_FALSE(reference.has_origin());
  EXPECT_EQ(sinu::board::encode_odometry(s, reference, {}, frame), 0u) << "nothing before alignment";

  s = sinu::test::sample_solution();
  reference.observe(s);
  s.P_nav.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() * 25.0;  // sigma_h 5 m: 50 %
  ASSERT_GT(sinu::board::encode_odometry(s, reference, {}, frame), 0u);
  ref::Frame f = decode_one(frame);
  EXPECT_EQ(f.f("quality"), 50);
  EXPECT_NEAR(f.f("x"), 0.0, 1e-9);
  s.P_nav.topLeftCorner<3, 3>() = Eigen::Matrix3d::Identity() * 1e8;  // hopeless, but still valid: 1
  ASSERT_GT(sinu::board::encode_odometry(s, reference, {}, frame), 0u);
  EXPECT_EQ(decode_one(frame).f("quality"), 1);

  using namespace sinu::est::nav_flag;
  const std::array<std::uint32_t, 4> events = {kPositionReset, kVelocityReset, kYawReset, kPositionReset | kYawReset};
  for (const std::uint32_t event : events) {
    s.flags = kAligned | event;
    reference.observe(s);
  }
  s.flags = kAligned | kGnssPosFused;  // not a reset
  reference.observe(s);
  s.flags = kAligned | kLost;
  ASSERT_GT(sinu::board::encode_odometry(s, reference, {}, frame), 0u);
  f = decode_one(frame);
  EXPECT_EQ(f.f("reset_counter"), 4);
  EXPECT_EQ(f.f("quality"), -1) << "-1 = odometry has failed";
}

// ---- GPS_INPUT -----------------------------------------------------------

TEST(GpsTime, KnownWeeks) {
  // 2017-01-01T00:00:00Z, a Sunday: GPS week 1930 started 18 s before (GPS - UTC = 18 s).
  const auto w = sinu::board::gps_week_time(1'483'228'800'000);
  EXPECT_EQ(w.week, 1930);
  EXPECT_EQ(w.time_of_week_ms, 18'000u);
  EXPECT_EQ(sinu::board::gps_week_time(0).week, 0) << "before the GPS epoch";
}

TEST(MavlinkMessages, GpsInputFields) {
  const NavSolution s = sinu::test::sample_solution();
  mav::MavlinkFrame frame;
  ASSERT_GT(sinu::board::encode_gps_input(s, {5, 1, 191}, frame), 0u);
  const ref::Frame f = decode_one(frame);
  EXPECT_EQ(f.msgid, 232u);
  EXPECT_EQ(f.len, 65u);
  EXPECT_EQ(f.f("time_usec"), 12'345'678);
  EXPECT_EQ(f.f("gps_id"), 0);
  EXPECT_EQ(f.f("ignore_flags"), 4);  // GPS_INPUT_IGNORE_FLAG_VDOP only
  // GPS week time from the calendar, independently of the encoder's constants.
  using namespace std::chrono;
  const sys_time<milliseconds> utc{milliseconds{s.utc_ms}};
  const auto gps = utc - sys_days{year{1980} / January / 6} + seconds{18};
  EXPECT_EQ(f.f("time_week"), static_cast<double>(floor<weeks>(gps).count()));
  EXPECT_EQ(f.f("time_week_ms"), static_cast<double>((gps - floor<weeks>(gps)).count()));
  EXPECT_EQ(f.f("time_week"), 2411);
  EXPECT_EQ(f.f("fix_type"), 3);
  EXPECT_EQ(f.f("lat"), std::round(s.lat_deg * 1e7));
  EXPECT_EQ(f.f("lon"), std::round(s.lon_deg * 1e7));
  EXPECT_NEAR(f.f("alt"), 45.3 + 12.1, 1e-4) << "MSL = ellipsoidal - geoid separation";
  EXPECT_NEAR(f.f("hdop"), 0.8, 1e-6);
  EXPECT_EQ(f.f("vdop"), 65535.0);
  EXPECT_NEAR(f.f("vn"), 8.0, 1e-6);
  EXPECT_NEAR(f.f("ve"), -3.0, 1e-6);
  EXPECT_NEAR(f.f("vd"), 0.5, 1e-6);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> h(s.P_nav.topLeftCorner<2, 2>());
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> v(s.P_nav.block<3, 3>(3, 3));
  EXPECT_NEAR(f.f("horiz_accuracy"), std::sqrt(h.eigenvalues().maxCoeff()), 1e-5);
  EXPECT_NEAR(f.f("vert_accuracy"), std::sqrt(s.P_nav(2, 2)), 1e-5);
  EXPECT_NEAR(f.f("speed_accuracy"), std::sqrt(v.eigenvalues().maxCoeff()), 1e-6);
  EXPECT_EQ(f.f("satellites_visible"), 14);
  EXPECT_EQ(f.f("yaw"), 12000) << "120 deg";
}

TEST(MavlinkMessages, GpsInputYawNorthAndWithoutFix) {
  NavSolution s = sinu::test::sample_solution();
  mav::MavlinkFrame frame;
  s.q_nb = sinu::test::q_from_rpy(0.0, 0.0, -0.001 * kDeg);  // rounds to 0 cdeg: north is 36000
  ASSERT_GT(sinu::board::encode_gps_input(s, {}, frame), 0u);
  EXPECT_EQ(decode_one(frame).f("yaw"), 36000);
  s.q_nb = sinu::test::q_from_rpy(0.0, 0.0, -90.0 * kDeg);
  ASSERT_GT(sinu::board::encode_gps_input(s, {}, frame), 0u);
  EXPECT_EQ(decode_one(frame).f("yaw"), 27000);
  s.P_nav(8, 8) = std::pow(10.0 * kDeg, 2);  // heading not known well enough
  ASSERT_GT(sinu::board::encode_gps_input(s, {}, frame), 0u);
  EXPECT_EQ(decode_one(frame).f("yaw"), 0) << "0 = not available";

  // Lost, no satellites, no UTC: no fix, hdop unknown, yaw and satellites 0:
  // the payload ends in zeros and is truncated.
  s = sinu::test::sample_solution();
  s.flags |= sinu::est::nav_flag::kLost;
  s.satellites = 0;
  s.has_utc = false;
  ASSERT_GT(sinu::board::encode_gps_input(s, {}, frame), 0u);
  const ref::Frame f = decode_one(frame);
  EXPECT_EQ(f.len, 62u) << "yaw (2 bytes) and satellites_visible (1) truncated";
  EXPECT_EQ(f.payload.size(), 65u);
  EXPECT_EQ(f.f("fix_type"), 1);  // GPS_FIX_TYPE_NO_FIX
  EXPECT_EQ(f.f("ignore_flags"), 4 | 2);
  EXPECT_EQ(f.f("hdop"), 65535.0);
  EXPECT_EQ(f.f("time_week"), 0);
  EXPECT_EQ(f.f("time_week_ms"), 0);
  EXPECT_EQ(f.f("yaw"), 0);
}

// ---- schedule ------------------------------------------------------------

TEST(RateSchedule, WholePeriodsAndNoBurstAfterAGap) {
  sinu::board::RateSchedule every_100ms(10.0);
  int sent = 0;
  for (int k = 0; k < 100; ++k) sent += every_100ms.due(k * 0.01) ? 1 : 0;  // 1 s of 100 Hz solutions
  EXPECT_EQ(sent, 10);
  EXPECT_TRUE(every_100ms.due(5.0)) << "after a 4 s gap";
  EXPECT_FALSE(every_100ms.due(5.01));
  EXPECT_TRUE(every_100ms.due(5.1));
  sinu::board::RateSchedule off(0.0);
  EXPECT_FALSE(off.due(0.0));
}

}  // namespace
