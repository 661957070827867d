#pragma once
// The navigation log, nav.csv: the truth.csv columns (t, lat, lon, h, vn, ve,
// vd, roll, pitch, yaw), the NED sigmas, the sensor-error estimates with
// their sigmas, the nav_flag bits (events since the previous row kept), the
// largest test ratio of each aiding source since the previous row, and every
// effect state the layout carries (empty fields while a reserved one is off).
// The same file from `sinu fly` on the board and from `sinu replay`.
#include <array>
#include <string>

#include "estimator/nav/navigator.hpp"
#include "firmware/board/outputs/text_sink.hpp"

namespace sinu::board {

class NavLog {
 public:
  /// Creates `path` and writes the header for `layout`; `period_s` between
  /// rows (0: every solution). False if the file cannot be created.
  bool open(const std::string& path, const est::StateLayout& layout, double period_s);
  /// One solution; a row is written once a period has passed.
  void on_nav(const est::NavOutput& out, const est::ErrorStateFilter& filter);
  /// Pushes buffered rows to the file (at most this much is lost on a crash).
  void flush() { out_.flush(); }
  /// False if any write failed (disk full).
  bool close() { return out_.close(); }
  const std::string& path() const { return out_.path(); }

  static std::string header(const est::StateLayout& layout);

 private:
  void write(const est::NavOutput& o, const est::ErrorStateFilter& filter);

  TextSink out_;
  double period_s_ = 0.0;
  double next_write_t_ = -1e300;
  std::uint32_t flags_ = 0;
  std::array<double, est::kAidingSourceCount> test_ratio_{};
};

}  // namespace sinu::board
