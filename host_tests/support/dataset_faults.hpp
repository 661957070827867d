#pragma once
// Fault injection for dataset folders (dataset-format.md): copies imu.csv,
// gps.nmea, truth.csv and meta.json from one folder to another, applying
// faults a real unit meets in flight, each at a known time window
// [start_s, start_s + duration_s) of the files' own clock (imu.csv `t`, the
// gps.nmea arrival prefix). For the fault-injection test suites.
//
// What is written, exactly:
//  - Every line not touched by a fault is copied byte for byte, with its own
//    terminator (LF or CR LF; a last line without LF stays without one).
//    The imu.csv and truth.csv header lines are never changed.
//  - A line whose time cannot be read (empty, garbage before the first comma)
//    is outside every window and is never changed or removed.
//  - truth.csv and meta.json are copied unchanged, except that
//    DropLeadingSeconds filters truth.csv too.
//  - Faults apply in the order given, each to the output of the previous one.
//  - Changed numbers in imu.csv are printed as the shortest text that reads
//    back to the same double (std::to_chars), so +-full scale reads back
//    exactly; the other fields of the row stay byte for byte.
#include <array>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <variant>
#include <vector>

namespace sinu::test {

/// Every GGA, RMC and GLL (any talker) arriving in the window that is well
/// framed with a valid checksum and carries a position: latitude and
/// longitude moved by offset_ned_m[0] north and [1] east, converted at the
/// sentence's own latitude with the WGS-84 meridian and transverse radii on
/// the ellipsoid (dlat = dN / R_M, dlon = dE / (R_N cos lat)); GGA's altitude
/// lowered by offset_ned_m[2] (down). Each field keeps its decimals (ddmm.mmmm
/// rounded to the same number of minute decimals, altitude to the same
/// decimals) and the hemisphere letter follows the sign (latitude clamped to
/// +-90 deg, longitude wrapped into [-180, 180]). The checksum is recomputed
/// in the case the sentence used. Everything else (speed, course, time, other
/// sentences, corrupt sentences, sentences without a fix) is left alone; a
/// zero component leaves its field's text untouched.
struct GnssPositionJump {
  double start_s = 0.0, duration_s = 0.0;
  std::array<double, 3> offset_ned_m{};
};

/// Every gps.nmea line in the window keeps its "ARRIVAL," prefix byte for
/// byte and gets a garbage sentence instead of its own, one of (uniformly):
///  - noise: 8..120 random bytes, mostly printable, at least one control or
///    high byte;
///  - truncated: the original sentence cut before its '*' (no checksum left);
///  - wrong checksum: the original up to its '*', then '*' and two hex digits
///    that do not match;
///  - binary: 16..200 random bytes 0x00..0xFF, at least one non-printable.
/// Never an LF or CR inside a line, never longer than 250 bytes; each one
/// fails NMEA framing or checksum by construction. Deterministic for a seed
/// (std::mt19937_64, whose sequence the C++ standard fixes).
struct GnssGarbage {
  double start_s = 0.0, duration_s = 0.0;
  std::uint64_t seed = 1;
};

/// gps.nmea lines in the window removed.
struct GnssOutage {
  double start_s = 0.0, duration_s = 0.0;
};

enum class ClipMode {
  /// Each chosen axis reads direction * full scale (the sensor pegged).
  Pegged,
  /// Each chosen axis reads clamp(v + A fs sin(2 pi f (t - start_s) + phase), -fs, fs)
  /// with v the recorded value, A = vibration_amplitude_fs, f = vibration_hz,
  /// phase = vibration_phase_rad[axis]: a clipped vibration burst, whose
  /// asymmetric rectification shifts the mean of an axis that was not at zero.
  Vibration,
};

/// imu.csv rows in the window: accelerometer axes (and gyro axes, when
/// gyro_full_scale_rad_s > 0) clipped at their full scale. An axis is chosen
/// when its direction is nonzero (only the sign matters, and only for
/// Pegged). Empty fields (no sample) stay empty.
struct ImuClip {
  double start_s = 0.0, duration_s = 0.0;
  double accel_full_scale_m_s2 = 2.0 * 9.80665;
  double gyro_full_scale_rad_s = 0.0;  // 0: gyro untouched
  ClipMode mode = ClipMode::Pegged;
  std::array<int, 3> accel_direction{1, 1, 1};
  std::array<int, 3> gyro_direction{1, 1, 1};
  double vibration_amplitude_fs = 3.0;
  double vibration_hz = 7.3;  // not a divisor of usual IMU rates: the samples sweep the phase
  std::array<double, 3> vibration_phase_rad{0.0, 2.1, 4.2};  // per axis, gyro axes use the same
};

/// imu.csv rows in the window removed.
struct ImuGap {
  double start_s = 0.0, duration_s = 0.0;
};

/// The first `count` imu.csv rows get empty mx, my, mz fields (a
/// magnetometer slower than the IMU; legal in the contract).
struct ImuDropMagFirstRows {
  std::size_t count = 0;
};

/// A unit that rebooted in the air: every imu.csv row, gps.nmea line and
/// truth.csv row with a time before t0 + seconds removed, t0 the first
/// imu.csv `t`.
struct DropLeadingSeconds {
  double seconds = 0.0;
};

/// The part before a reboot: every line with a time at or after t0 + seconds
/// removed (t0 the first imu.csv `t`).
struct KeepLeadingSeconds {
  double seconds = 0.0;
};

/// A live stream's clock glitch: the first imu.csv row at or after `at_s`
/// gets the time of the row before it (Repeat), or that time minus
/// `step_back_s` (Backwards). Breaks the contract's "strictly increasing" on
/// purpose: what a board's HAL time stamps can do.
enum class TimeGlitchKind { Repeat, Backwards };
struct ImuTimeGlitch {
  double at_s = 0.0;
  TimeGlitchKind kind = TimeGlitchKind::Repeat;
  double step_back_s = 0.5;
};

/// imu.csv rows in the window: ax and gx written as "nan" (strtod reads it:
/// what a driver that divides by a zero scale would deliver).
struct ImuNonFinite {
  double start_s = 0.0, duration_s = 0.0;
};

/// From `start_s` on, `delta` added to imu.csv column `column` (1..6: ax..gz):
/// a bias that shifts in flight (a knock, a clipping burst, vibration that
/// changes with the throttle), beyond what the calibrated model allows.
struct ImuBiasShift {
  double start_s = 0.0;
  std::size_t column = 3;  // az
  double delta = 0.0;      // m/s^2 or rad/s
};

using Fault = std::variant<GnssPositionJump, GnssGarbage, GnssOutage, ImuClip, ImuGap, ImuDropMagFirstRows,
                           DropLeadingSeconds, KeepLeadingSeconds, ImuTimeGlitch, ImuNonFinite, ImuBiasShift>;

/// What one fault did: lines (rows) it rewrote and lines it removed, over all files.
struct FaultEffect {
  std::size_t changed = 0, removed = 0;
};

/// Copies the dataset at `src` into `dst` (created if needed; may be `src`)
/// applying `faults` in order; one FaultEffect per fault. Files absent from
/// `src` (gps.nmea, truth.csv, meta.json are optional) stay absent. Throws
/// std::runtime_error if imu.csv is missing or a file cannot be read or written.
std::vector<FaultEffect> inject_faults(const std::filesystem::path& src, const std::filesystem::path& dst,
                                       const std::vector<Fault>& faults);

/// First and last readable time of one file; NaN when it has none.
struct TimeSpan {
  double first_s = std::numeric_limits<double>::quiet_NaN();
  double last_s = std::numeric_limits<double>::quiet_NaN();
};

/// imu.csv `t` and gps.nmea arrival times of a dataset (for placing faults at
/// "t0 + X"); a missing gps.nmea gives a NaN span.
struct DatasetTimes {
  TimeSpan imu, gps;
};
DatasetTimes dataset_times(const std::filesystem::path& dir);

}  // namespace sinu::test
