#pragma once
// The navigation solution as MAVLink messages (common.xml definitions; the
// field tables are in mavlink_definitions.hpp). Each encoder fills one frame
// and returns its size (0: nothing to send). No allocation.
//
// Frames: the solution's own, body FRD and NED (docs/architecture.md).
//
// HEARTBEAT (0): type MAV_TYPE_ONBOARD_CONTROLLER, autopilot MAV_AUTOPILOT_INVALID
//   ("Use MAV_AUTOPILOT_INVALID for components that are not flight
//   controllers"), base_mode 0, custom_mode 0, system_status MAV_STATE_ACTIVE
//   while navigating (aligned and not lost) else MAV_STATE_STANDBY.
//
// ODOMETRY (331), only once aligned (no origin and no estimate before):
//   time_usec       board monotonic time [us] ("time since system boot")
//   frame_id        MAV_FRAME_LOCAL_NED: x y z [m] north, east, down from the
//                   origin of OdometryReference (first aligned solution)
//   q               w x y z, body FRD -> NED (v_ned = q v_body), normalised
//   child_frame_id  MAV_FRAME_BODY_FRD: "Coordinate frame of reference for the
//                   velocity in free space (twist) data", so vx vy vz [m/s] are
//                   the velocity in body FRD axes, v_b = C_bn v_ned
//   roll/pitch/yawspeed  body angular rate [rad/s] about FRD x, y, z
//   pose_covariance      upper triangle, row-major, of the 6x6 covariance of
//                   (x y z [m], roll pitch yaw [rad]) (nav_uncertainty.hpp)
//   velocity_covariance  upper triangle of the 6x6 of (vx vy vz, rates): the
//                   body-velocity 3x3 block; NaN for the rate entries (the
//                   solution carries no rate covariance; NaN is the field's
//                   "unknown", and the first element stays valid)
//   reset_counter   OdometryReference::reset_counter()
//   estimator_type  MAV_ESTIMATOR_TYPE_GPS_INS ("integrating GPS and inertial sensing")
//   quality         -1 when lost ("-1 = odometry has failed"), else
//                   odometry_quality(): 100 s / (s + sigma_h), s = 5 m
//
// GPS_INPUT (232), always (fix_type says whether it holds a position):
//   time_usec board time [us]; gps_id 0; time_week / time_week_ms GPS time of
//   utc_ms (0 / 0 without UTC); fix_type GPS_FIX_TYPE_3D_FIX while navigating,
//   else GPS_FIX_TYPE_NO_FIX ("No position information, GPS is connected");
//   lat lon [degE7]; alt [m] MSL = h_ellipsoid - geoid_sep; hdop of the last
//   fix; vdop UINT16_MAX (unknown) and ignored; vn ve vd [m/s] NED;
//   speed_accuracy, horiz_accuracy, vert_accuracy: 1-sigma from P_nav
//   (worst direction, nav_uncertainty.hpp); satellites_visible of the last
//   fix; yaw [cdeg] 1..36000 (36000 = north) while navigating with a yaw
//   sigma below 5 deg, else 0 ("zero means not available").
//   ignore_flags: GPS_INPUT_IGNORE_FLAG_VDOP always, _HDOP without a fix
//   ("All other fields must be provided").
#include <cstddef>
#include <cstdint>

#include "firmware/board/nav_solution.hpp"
#include "firmware/board/outputs/mavlink_frame.hpp"
#include "firmware/board/outputs/odometry_reference.hpp"

namespace sinu::board {

/// Aligned and not lost: the solution can be trusted.
bool navigating(const NavSolution& sol);

/// sigma_h [m] at which ODOMETRY's quality is 50 %.
inline constexpr double kQualityHalfSigmaM = 5.0;
/// ODOMETRY's quality [%], 1..100 from the horizontal sigma; -1 when lost.
std::int8_t odometry_quality(const NavSolution& sol);

std::size_t encode_heartbeat(const NavSolution& sol, const mavlink::FrameHeader& header, mavlink::MavlinkFrame& out);
std::size_t encode_odometry(const NavSolution& sol, const OdometryReference& reference,
                            const mavlink::FrameHeader& header, mavlink::MavlinkFrame& out);
std::size_t encode_gps_input(const NavSolution& sol, const mavlink::FrameHeader& header, mavlink::MavlinkFrame& out);

}  // namespace sinu::board
