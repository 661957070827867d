#pragma once
// A replay's nav.csv against the dataset's truth.csv, for the tests: the
// horizontal, height and yaw error of every nav.csv row (truth interpolated
// linearly in time; the yaw NaN where truth has none), the filter's height
// sigma and the row's health flags; window statistics over it.
#include <cstdint>
#include <string>
#include <vector>

namespace sinu::test {

struct ErrorSeries {
  std::vector<double> t, err_h, err_yaw_deg, err_vd_m_s;  // err_vd: NaN where truth has no vd
  std::vector<double> err_tilt_deg;  // hypot of the roll and pitch errors (NaN where truth has none)
  std::vector<double> err_height_m, sigma_pd_m;           // nav h - truth h (NaN where truth has none); its sigma
  std::vector<std::uint32_t> flags;
};

ErrorSeries error_series(const std::string& nav_csv, const std::string& truth_csv);
/// Over rows with from <= t < to (NaN / 0 when there are none).
double rms_between(const ErrorSeries& s, double from, double to);  // of err_h
/// RMS of x over from <= t < to, NaN values skipped (NaN when none is left).
double rms_of(const std::vector<double>& t, const std::vector<double>& x, double from, double to);
double max_between(const ErrorSeries& s, double from, double to);
std::uint32_t flags_between(const ErrorSeries& s, double from, double to);
/// Column `name` of nav.csv's first or last data row (NaN and a test failure
/// when the column is missing).
enum class NavRow { First, Last };
double nav_value(const std::string& nav_csv, const std::string& name, NavRow row);
/// Column `name` of the first nav.csv row at least `after_first_s` past the first row.
double nav_value_after(const std::string& nav_csv, const std::string& name, double after_first_s);

}  // namespace sinu::test
