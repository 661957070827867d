#pragma once
// The messages sinu sends, transcribed from the official definitions
// (mavlink/mavlink message_definitions/v1.0: minimal.xml for HEARTBEAT,
// common.xml for GPS_INPUT and ODOMETRY): fields in XML order, extensions
// marked. This is the only field table of the encoder; the wire layout and
// CRC_EXTRA follow from it (mavlink_message_def.hpp). Enum values used in the
// fields are below, with the XML's names.
#include "firmware/board/outputs/mavlink_message_def.hpp"

namespace sinu::board::mavlink {

using enum WireType;

// HEARTBEAT (0). mavlink_version is the XML's `uint8_t_mavlink_version`.
inline constexpr MessageDef<6> kHeartbeatDef{"HEARTBEAT", 0, {{
    {Uint8, "type"},
    {Uint8, "autopilot"},
    {Uint8, "base_mode"},
    {Uint32, "custom_mode"},
    {Uint8, "system_status"},
    {Uint8, "mavlink_version"},
}}};

// GPS_INPUT (232).
inline constexpr MessageDef<19> kGpsInputDef{"GPS_INPUT", 232, {{
    {Uint64, "time_usec"},           // [us]
    {Uint8, "gps_id"},
    {Uint16, "ignore_flags"},        // GPS_INPUT_IGNORE_FLAGS
    {Uint32, "time_week_ms"},        // [ms] GPS time from the start of the GPS week
    {Uint16, "time_week"},           // GPS week number
    {Uint8, "fix_type"},             // GPS_FIX_TYPE
    {Int32, "lat"},                  // [degE7] WGS84
    {Int32, "lon"},                  // [degE7] WGS84
    {Float, "alt"},                  // [m] MSL, positive up
    {Float, "hdop"},                 // UINT16_MAX if unknown
    {Float, "vdop"},                 // UINT16_MAX if unknown
    {Float, "vn"},                   // [m/s] earth-fixed NED
    {Float, "ve"},                   // [m/s]
    {Float, "vd"},                   // [m/s]
    {Float, "speed_accuracy"},       // [m/s]
    {Float, "horiz_accuracy"},       // [m]
    {Float, "vert_accuracy"},        // [m]
    {Uint8, "satellites_visible"},
    {Uint16, "yaw", 0, true},        // [cdeg] extension: 0 not available, 36000 north
}}};

// ODOMETRY (331).
inline constexpr MessageDef<18> kOdometryDef{"ODOMETRY", 331, {{
    {Uint64, "time_usec"},               // [us]
    {Uint8, "frame_id"},                 // MAV_FRAME of the pose
    {Uint8, "child_frame_id"},           // MAV_FRAME of the velocity (twist)
    {Float, "x"},                        // [m]
    {Float, "y"},                        // [m]
    {Float, "z"},                        // [m]
    {Float, "q", 4},                     // w, x, y, z
    {Float, "vx"},                       // [m/s]
    {Float, "vy"},                       // [m/s]
    {Float, "vz"},                       // [m/s]
    {Float, "rollspeed"},                // [rad/s]
    {Float, "pitchspeed"},               // [rad/s]
    {Float, "yawspeed"},                 // [rad/s]
    {Float, "pose_covariance", 21},      // upper triangle of 6x6 (x y z roll pitch yaw), row-major
    {Float, "velocity_covariance", 21},  // upper triangle of 6x6 (vx vy vz rollspeed pitchspeed yawspeed)
    {Uint8, "reset_counter", 0, true},
    {Uint8, "estimator_type", 0, true},  // MAV_ESTIMATOR_TYPE
    {Int8, "quality", 0, true},          // [%] -1 failed, 0 unknown, 1 worst .. 100 best
}}};

inline constexpr MessageInfo kHeartbeat = message_info(kHeartbeatDef);
inline constexpr MessageInfo kGpsInput = message_info(kGpsInputDef);
inline constexpr MessageInfo kOdometry = message_info(kOdometryDef);

// Enum values (minimal.xml, common.xml).
inline constexpr std::uint8_t kMavTypeOnboardController = 18;  // MAV_TYPE_ONBOARD_CONTROLLER
inline constexpr std::uint8_t kMavAutopilotInvalid = 8;        // MAV_AUTOPILOT_INVALID: not a flight controller
inline constexpr std::uint8_t kMavStateStandby = 3;            // MAV_STATE_STANDBY
inline constexpr std::uint8_t kMavStateActive = 4;             // MAV_STATE_ACTIVE
inline constexpr std::uint8_t kMavlinkVersion = 3;             // the value the generator puts in mavlink_version
inline constexpr std::uint8_t kMavFrameLocalNed = 1;           // MAV_FRAME_LOCAL_NED
inline constexpr std::uint8_t kMavFrameBodyFrd = 12;           // MAV_FRAME_BODY_FRD
inline constexpr std::uint8_t kMavEstimatorTypeGpsIns = 5;     // MAV_ESTIMATOR_TYPE_GPS_INS
inline constexpr std::uint8_t kGpsFixTypeNoFix = 1;            // GPS_FIX_TYPE_NO_FIX: connected, no position
inline constexpr std::uint8_t kGpsFixType3d = 3;               // GPS_FIX_TYPE_3D_FIX
inline constexpr std::uint16_t kGpsInputIgnoreHdop = 2;        // GPS_INPUT_IGNORE_FLAG_HDOP
inline constexpr std::uint16_t kGpsInputIgnoreVdop = 4;        // GPS_INPUT_IGNORE_FLAG_VDOP
inline constexpr std::uint8_t kMavCompIdOnboardComputer = 191; // MAV_COMP_ID_ONBOARD_COMPUTER

}  // namespace sinu::board::mavlink
