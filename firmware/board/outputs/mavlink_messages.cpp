#include "firmware/board/outputs/mavlink_messages.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include "estimator/nav/nav_health.hpp"
#include "firmware/board/outputs/gps_time.hpp"
#include "firmware/board/outputs/mavlink_definitions.hpp"
#include "firmware/board/outputs/mavlink_payload.hpp"
#include "firmware/board/outputs/nav_uncertainty.hpp"

namespace sinu::board {

namespace {

using mavlink::field;
using mavlink::Payload;

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
constexpr double kYawSigmaMaxRad = 5.0 / kDegPerRad;  // GPS_INPUT yaw sent only when better than this
constexpr float kUnknownDop = 65535.0f;               // UINT16_MAX: the definition's "unknown"

std::uint64_t board_time_us(const NavSolution& sol) {
  return sol.t_s > 0.0 ? static_cast<std::uint64_t>(std::llround(sol.t_s * 1e6)) : 0u;
}

std::int32_t deg_e7(double deg) {
  return static_cast<std::int32_t>(std::clamp(std::llround(deg * 1e7), -1'800'000'000LL, 1'800'000'000LL));
}

/// Upper-right triangle, row-major: (0,0) (0,1) .. (0,5) (1,1) .. (5,5).
std::array<float, 21> upper_triangle(const Eigen::Matrix<double, 6, 6>& M) {
  std::array<float, 21> out{};
  std::size_t k = 0;
  for (Eigen::Index r = 0; r < 6; ++r)
    for (Eigen::Index c = r; c < 6; ++c) out[k++] = static_cast<float>(0.5 * (M(r, c) + M(c, r)));
  return out;
}

std::size_t finish(const Payload& p, const mavlink::MessageInfo& info, const mavlink::FrameHeader& header,
                   mavlink::MavlinkFrame& out) {
  return mavlink::encode_frame(info, p.bytes(info.length), header, out);
}

}  // namespace

bool navigating(const NavSolution& sol) { return sol.aligned && (sol.flags & est::nav_flag::kLost) == 0; }

std::int8_t odometry_quality(const NavSolution& sol) {
  if (!navigating(sol)) return -1;
  const double q = 100.0 * kQualityHalfSigmaM / (kQualityHalfSigmaM + horizontal_sigma_m(sol));
  return static_cast<std::int8_t>(std::clamp(std::lround(q), 1L, 100L));  // 0 would mean "unknown"
}

std::size_t encode_heartbeat(const NavSolution& sol, const mavlink::FrameHeader& header, mavlink::MavlinkFrame& out) {
  constexpr auto& D = mavlink::kHeartbeatDef;
  Payload p;
  p.put<field(D, "type")>(mavlink::kMavTypeOnboardController);
  p.put<field(D, "autopilot")>(mavlink::kMavAutopilotInvalid);
  p.put<field(D, "base_mode")>(std::uint8_t{0});
  p.put<field(D, "custom_mode")>(std::uint32_t{0});
  p.put<field(D, "system_status")>(navigating(sol) ? mavlink::kMavStateActive : mavlink::kMavStateStandby);
  p.put<field(D, "mavlink_version")>(mavlink::kMavlinkVersion);
  return finish(p, mavlink::kHeartbeat, header, out);
}

std::size_t encode_odometry(const NavSolution& sol, const OdometryReference& reference,
                            const mavlink::FrameHeader& header, mavlink::MavlinkFrame& out) {
  out.size = 0;
  if (!sol.aligned || !reference.has_origin()) return 0;
  constexpr auto& D = mavlink::kOdometryDef;
  const Eigen::Quaterniond q_nb = sol.q_nb.normalized();
  const Eigen::Vector3d r_m = reference.local_ned_m(sol);
  const Eigen::Vector3d v_b = q_nb.conjugate() * sol.v_ned_m_s;
  const Eigen::Vector3d& w_b = sol.angular_rate_b_rad_s;
  Eigen::Matrix<double, 6, 6> P_twist = Eigen::Matrix<double, 6, 6>::Constant(std::numeric_limits<double>::quiet_NaN());
  P_twist.topLeftCorner<3, 3>() = body_velocity_covariance(sol);

  Payload p;
  p.put<field(D, "time_usec")>(board_time_us(sol));
  p.put<field(D, "frame_id")>(mavlink::kMavFrameLocalNed);
  p.put<field(D, "child_frame_id")>(mavlink::kMavFrameBodyFrd);
  p.put<field(D, "x")>(static_cast<float>(r_m.x()));
  p.put<field(D, "y")>(static_cast<float>(r_m.y()));
  p.put<field(D, "z")>(static_cast<float>(r_m.z()));
  p.put_array<field(D, "q")>(std::array<float, 4>{static_cast<float>(q_nb.w()), static_cast<float>(q_nb.x()),
                                                  static_cast<float>(q_nb.y()), static_cast<float>(q_nb.z())});
  p.put<field(D, "vx")>(static_cast<float>(v_b.x()));
  p.put<field(D, "vy")>(static_cast<float>(v_b.y()));
  p.put<field(D, "vz")>(static_cast<float>(v_b.z()));
  p.put<field(D, "rollspeed")>(static_cast<float>(w_b.x()));
  p.put<field(D, "pitchspeed")>(static_cast<float>(w_b.y()));
  p.put<field(D, "yawspeed")>(static_cast<float>(w_b.z()));
  p.put_array<field(D, "pose_covariance")>(upper_triangle(pose_covariance(sol)));
  p.put_array<field(D, "velocity_covariance")>(upper_triangle(P_twist));
  p.put<field(D, "reset_counter")>(reference.reset_counter());
  p.put<field(D, "estimator_type")>(mavlink::kMavEstimatorTypeGpsIns);
  p.put<field(D, "quality")>(odometry_quality(sol));
  return finish(p, mavlink::kOdometry, header, out);
}

std::size_t encode_gps_input(const NavSolution& sol, const mavlink::FrameHeader& header, mavlink::MavlinkFrame& out) {
  constexpr auto& D = mavlink::kGpsInputDef;
  const bool fix = navigating(sol);
  const GpsWeekTime gps = sol.has_utc ? gps_week_time(sol.utc_ms) : GpsWeekTime{};
  const bool hdop_known = sol.satellites > 0 && std::isfinite(sol.hdop) && sol.hdop > 0.0;
  std::uint16_t ignore = mavlink::kGpsInputIgnoreVdop;
  if (!hdop_known) ignore = static_cast<std::uint16_t>(ignore | mavlink::kGpsInputIgnoreHdop);
  std::uint16_t yaw_cdeg = 0;
  if (fix && std::sqrt(std::max(pose_covariance(sol)(5, 5), 0.0)) <= kYawSigmaMaxRad) {
    double yaw_deg = roll_pitch_yaw_rad(sol.q_nb).z() * kDegPerRad;
    if (yaw_deg < 0.0) yaw_deg += 360.0;
    const long cdeg = std::lround(yaw_deg * 100.0);
    yaw_cdeg = static_cast<std::uint16_t>(cdeg <= 0 || cdeg > 36000 ? 36000 : cdeg);  // north is 36000, never 0
  }

  Payload p;
  p.put<field(D, "time_usec")>(board_time_us(sol));
  p.put<field(D, "gps_id")>(std::uint8_t{0});
  p.put<field(D, "ignore_flags")>(ignore);
  p.put<field(D, "time_week_ms")>(gps.time_of_week_ms);
  p.put<field(D, "time_week")>(gps.week);
  p.put<field(D, "fix_type")>(fix ? mavlink::kGpsFixType3d : mavlink::kGpsFixTypeNoFix);
  p.put<field(D, "lat")>(deg_e7(sol.lat_deg));
  p.put<field(D, "lon")>(deg_e7(sol.lon_deg));
  p.put<field(D, "alt")>(static_cast<float>(sol.h_ellipsoid_m - sol.geoid_sep_m));
  p.put<field(D, "hdop")>(hdop_known ? static_cast<float>(sol.hdop) : kUnknownDop);
  p.put<field(D, "vdop")>(kUnknownDop);
  p.put<field(D, "vn")>(static_cast<float>(sol.v_ned_m_s.x()));
  p.put<field(D, "ve")>(static_cast<float>(sol.v_ned_m_s.y()));
  p.put<field(D, "vd")>(static_cast<float>(sol.v_ned_m_s.z()));
  p.put<field(D, "speed_accuracy")>(static_cast<float>(velocity_sigma_m_s(sol)));
  p.put<field(D, "horiz_accuracy")>(static_cast<float>(horizontal_sigma_m(sol)));
  p.put<field(D, "vert_accuracy")>(static_cast<float>(vertical_sigma_m(sol)));
  p.put<field(D, "satellites_visible")>(static_cast<std::uint8_t>(std::clamp(sol.satellites, 0, 255)));
  p.put<field(D, "yaw")>(yaw_cdeg);
  return finish(p, mavlink::kGpsInput, header, out);
}

}  // namespace sinu::board
