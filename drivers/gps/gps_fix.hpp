#pragma once
// One GPS epoch: everything the receiver said about the same UTC instant,
// gathered from GGA, RMC, VTG, GSA, GST, ZDA and GLL.
#include <optional>

#include "drivers/gps/nmea_messages.hpp"

namespace sinu::drivers {

struct GpsFix {
  double arrival_s = 0.0;  // board monotonic time the epoch's first sentence arrived
  UtcMs utc_ms = 0;        // the instant the fix refers to (UTC time of day)
  std::optional<UtcDate> date;
  std::optional<double> lat_deg, lon_deg;
  std::optional<double> alt_msl_m, geoid_sep_m;
  int quality = 0;  // GGA fix quality (0 = no fix, 6 = estimated: the receiver dead reckoning)
  bool rmc_valid = false;
  char rmc_mode = 0, vtg_mode = 0;  // NMEA 2.3 mode indicators (0 when absent; E estimated, N not valid)
  std::optional<int> sats;
  std::optional<double> hdop, pdop, vdop;
  std::optional<double> speed_m_s, course_deg;
  std::optional<double> sigma_lat_m, sigma_lon_m, sigma_alt_m;  // from GST
  bool has_gga = false, has_rmc = false, has_gst = false;
  bool has_gll = false, gll_valid = false;

  /// A usable position: GGA says fixed, or (without GGA) RMC says valid, or
  /// (with neither) GLL says valid; never one the receiver only extrapolated
  /// (GGA quality 6, mode E: gpsd's "dead reckoning"): the INS does that
  /// better, and fusing it would hide an outage.
  bool has_position() const {
    return lat_deg && lon_deg && !estimated() && (has_gga ? quality > 0 : has_rmc ? rmc_valid : gll_valid);
  }
  /// The speed and course are a measurement (not from an invalid or extrapolating receiver).
  bool has_velocity() const { return speed_m_s && course_deg && !estimated() && (!has_rmc || rmc_valid); }
  /// A sentence of the epoch says the receiver is extrapolating or its data are not valid.
  bool estimated() const {
    constexpr int kGgaEstimated = 6;
    auto not_measured = [](char mode) { return mode == 'E' || mode == 'N'; };
    return (has_gga && quality == kGgaEstimated) || not_measured(rmc_mode) || not_measured(vtg_mode);
  }
  /// A position without a height (RMC or GLL, no GGA): the INS cannot start from it.
  bool horizontal_only() const { return has_position() && !alt_msl_m; }
  /// WGS-84 ellipsoidal height = altitude above MSL + geoid separation.
  std::optional<double> ellipsoid_height_m() const {
    if (!alt_msl_m) return std::nullopt;
    return *alt_msl_m + geoid_sep_m.value_or(0.0);
  }
};

}  // namespace sinu::drivers
