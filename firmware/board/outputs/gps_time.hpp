#pragma once
// UTC -> GPS week and time of week. GPS time counts from 1980-01-06 00:00:00
// UTC without leap seconds, so GPS = UTC + the leap seconds inserted since.
#include <cstdint>

namespace sinu::board {

/// GPS - UTC [s]: 18 since 2017-01-01 (IERS Bulletin C; no leap second has
/// been inserted since). Change it when the IERS announces the next one.
inline constexpr std::int64_t kGpsMinusUtcS = 18;
inline constexpr std::int64_t kGpsEpochUnixS = 315'964'800;  // 1980-01-06T00:00:00Z in Unix seconds
inline constexpr std::int64_t kMsPerGpsWeek = 7LL * 86'400 * 1'000;

struct GpsWeekTime {
  std::uint16_t week = 0;              // full week number (not modulo 1024)
  std::uint32_t time_of_week_ms = 0;   // from the start of the week (Sunday 00:00:00 GPS)
};

/// GPS week time of `utc_ms` (ms since 1970-01-01 UTC); zero before the GPS epoch.
GpsWeekTime gps_week_time(std::int64_t utc_ms);

}  // namespace sinu::board
