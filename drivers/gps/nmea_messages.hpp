#pragma once
// Decoded NMEA sentences. An empty NMEA field is "not available": it stays an
// empty std::optional, never zero.
#include <cstdint>
#include <optional>
#include <variant>

namespace sinu::drivers {

/// UTC time of day in milliseconds (0 .. 86'400'999; a leap second may reach 86'400'xxx).
using UtcMs = std::int64_t;

struct UtcDate {
  int year = 0;   // four digits
  int month = 0;  // 1..12
  int day = 0;    // 1..31
  friend bool operator==(const UtcDate&, const UtcDate&) = default;
};

/// GGA: fix data.
struct GgaMessage {
  std::optional<UtcMs> utc_ms;
  std::optional<double> lat_deg, lon_deg;  // WGS-84, north and east positive
  int quality = 0;                         // 0 invalid, 1 GPS, 2 DGPS, 4 RTK fixed, 5 RTK float, 6 dead reckoning
  std::optional<int> sats;
  std::optional<double> hdop;
  std::optional<double> alt_msl_m;    // antenna altitude above mean sea level (geoid)
  std::optional<double> geoid_sep_m;  // geoid above WGS-84 ellipsoid
};

/// RMC: recommended minimum data.
struct RmcMessage {
  std::optional<UtcMs> utc_ms;
  bool valid = false;  // status 'A'
  std::optional<double> lat_deg, lon_deg;
  std::optional<double> speed_m_s;   // over ground
  std::optional<double> course_deg;  // over ground, true north, [0, 360)
  std::optional<UtcDate> date;
  char mode = 0;  // NMEA 2.3 mode indicator (A, D, E, F, R, N, ...), 0 when absent
};

/// VTG: course and speed over ground (carries no time: belongs to the current epoch).
struct VtgMessage {
  std::optional<double> course_deg;
  std::optional<double> speed_m_s;
  char mode = 0;
};

/// GSA: DOP and active satellites (no time either).
struct GsaMessage {
  int fix_type = 0;  // 1 none, 2 2D, 3 3D
  std::optional<double> pdop, hdop, vdop;
  int used_sats = 0;
};

/// GST: pseudorange error statistics, 1-sigma in metres.
struct GstMessage {
  std::optional<UtcMs> utc_ms;
  std::optional<double> rms_m;
  std::optional<double> sigma_lat_m, sigma_lon_m, sigma_alt_m;
};

/// GLL: position and time only (some receivers report every other epoch
/// with GLL instead of GGA/RMC: Garmin 48, Humminbird, Triton).
struct GllMessage {
  std::optional<UtcMs> utc_ms;
  std::optional<double> lat_deg, lon_deg;
  bool valid = false;  // status 'A' (and mode not 'N')
};

/// ZDA: date and time.
struct ZdaMessage {
  std::optional<UtcMs> utc_ms;
  std::optional<UtcDate> date;
};

using NmeaMessage =
    std::variant<GgaMessage, RmcMessage, VtgMessage, GsaMessage, GstMessage, ZdaMessage, GllMessage>;

}  // namespace sinu::drivers
