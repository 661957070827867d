// inject_faults: reads the dataset folder into memory, applies each fault in
// turn (faults/apply_*.cpp), writes the folder back out.
#include "host_tests/support/dataset_faults.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "host_tests/support/faults/apply.hpp"

namespace sinu::test {

namespace fs = std::filesystem;
using faults::DatasetText;
using faults::TextLines;

namespace {

std::optional<TextLines> read_lines_if_present(const fs::path& p) {
  if (!fs::exists(p)) return std::nullopt;
  return faults::split_lines(faults::read_bytes(p));
}

TimeSpan span_of(const std::optional<TextLines>& lines) {
  TimeSpan s;
  if (!lines) return s;
  for (const auto& l : *lines) {
    const auto t = faults::leading_number(l.text);
    if (!t) continue;
    if (std::isnan(s.first_s)) s.first_s = *t;
    s.last_s = *t;
  }
  return s;
}

}  // namespace

std::vector<FaultEffect> inject_faults(const fs::path& src, const fs::path& dst, const std::vector<Fault>& fault_list) {
  auto imu = read_lines_if_present(src / "imu.csv");
  if (!imu) throw std::runtime_error("no imu.csv in " + src.string());
  DatasetText d{std::move(*imu), read_lines_if_present(src / "gps.nmea"), read_lines_if_present(src / "truth.csv")};
  const fs::path meta_path = src / "meta.json";
  const std::optional<std::string> meta =
      fs::exists(meta_path) ? std::optional(faults::read_bytes(meta_path)) : std::nullopt;

  std::vector<FaultEffect> effects;
  for (const auto& fault : fault_list)
    effects.push_back(std::visit([&](const auto& f) { return faults::apply(f, d); }, fault));

  fs::create_directories(dst);
  faults::write_bytes(dst / "imu.csv", faults::join_lines(d.imu));
  if (d.gps) faults::write_bytes(dst / "gps.nmea", faults::join_lines(*d.gps));
  if (d.truth) faults::write_bytes(dst / "truth.csv", faults::join_lines(*d.truth));
  if (meta) faults::write_bytes(dst / "meta.json", *meta);
  return effects;
}

DatasetTimes dataset_times(const fs::path& dir) {
  return {span_of(read_lines_if_present(dir / "imu.csv")), span_of(read_lines_if_present(dir / "gps.nmea"))};
}

}  // namespace sinu::test
