#pragma once
// Helpers for the simulator tests: run a simulation into a temp folder, load
// its CSV files, and an Earth model written here independently of
// estimator/earth/wgs84 (different gravity formula, own radii and rates), so
// the tests check the simulator against a separate computation.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "firmware/host/dataset/csv_table.hpp"
#include "firmware/host/dataset/imu_csv.hpp"
#include "firmware/host/dataset/truth_csv.hpp"
#include "firmware/host/sim/simulation.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {

inline constexpr double kDeg = std::numbers::pi / 180.0;

/// All rows of a CSV file (the test fails on any read error).
inline std::vector<dataset::CsvRow> load_rows(const std::string& path, const dataset::CsvSchema& schema) {
  dataset::CsvReader reader(schema);
  std::vector<dataset::CsvRow> rows;
  EXPECT_TRUE(reader.open(path)) << reader.error().to_string();
  dataset::CsvRow row;
  dataset::ReadStatus s;
  while ((s = reader.next(row)) == dataset::ReadStatus::Row) rows.push_back(row);
  EXPECT_EQ(s, dataset::ReadStatus::End) << reader.error().to_string();
  return rows;
}

/// A simulated dataset in its own temp folder.
struct SimRun {
  TempDir dir;
  sim::SimResult result;
  std::string path(const char* file) const { return dir.file(file); }
  std::vector<dataset::CsvRow> imu() const { return load_rows(path("imu.csv"), dataset::kImuSchema); }
  std::vector<dataset::CsvRow> truth() const { return load_rows(path("truth.csv"), dataset::kTruthSchema); }
};

inline void run(SimRun& r, sim::SimOptions o) {
  o.out_dir = r.dir.path().string();
  dataset::Diagnostic err;
  ASSERT_TRUE(sim::run_simulation(o, r.result, err)) << err.to_string();
}

/// Error-free IMU and GPS: the outputs are the true motion exactly.
inline sim::SimOptions ideal_flight(std::uint64_t seed, double duration_s) {
  sim::SimOptions o;
  o.mode = sim::SimMode::Flight;
  o.seed = seed;
  o.duration_s = duration_s;
  o.error_model = sim::ideal_imu_error_model();
  o.gps.white_sigma_ned_m.setZero();
  o.gps.gm_sigma_ned_m.setZero();
  o.gps.velocity_sigma_ned_m_s.setZero();
  o.gps.corrupt_fraction = 0.0;
  return o;
}

// --- Independent WGS-84 reference ------------------------------------------
namespace ref {
inline constexpr double a = 6378137.0, f = 1.0 / 298.257223563, omega = 7.292115e-5;
inline constexpr double e2 = f * (2.0 - f);

inline double r_meridian(double lat) {
  const double s2 = std::sin(lat) * std::sin(lat);
  return a * (1.0 - e2) / std::pow(1.0 - e2 * s2, 1.5);
}
inline double r_transverse(double lat) { return a / std::sqrt(1.0 - e2 * std::sin(lat) * std::sin(lat)); }

/// Normal gravity: Somigliana's closed form with the equatorial and polar
/// values (TR8350.2), and the usual series in height
/// - (3.087691089e-6 - 4.397731e-9 sin^2 lat) h + 0.721e-12 h^2.
inline double gravity(double lat, double h) {
  constexpr double ge = 9.7803253359, gp = 9.8321849378, b = a * (1.0 - f);
  const double s2 = std::sin(lat) * std::sin(lat), c2 = 1.0 - s2;
  const double g0 = (a * ge * c2 + b * gp * s2) / std::sqrt(a * a * c2 + b * b * s2);
  return g0 - (3.087691089e-6 - 4.397731e-9 * s2) * h + 0.721e-12 * h * h;
}
inline Eigen::Vector3d earth_rate_n(double lat) { return {omega * std::cos(lat), 0.0, -omega * std::sin(lat)}; }
inline Eigen::Vector3d transport_rate_n(double lat, double h, const Eigen::Vector3d& v) {
  const double rn = r_transverse(lat) + h, rm = r_meridian(lat) + h;
  return {v.y() / rn, -v.x() / rm, -v.y() * std::tan(lat) / rn};
}
/// Body FRD -> NED from Euler ZYX [rad], written out element by element.
inline Eigen::Matrix3d C_nb(double roll, double pitch, double yaw) {
  const double cr = std::cos(roll), sr = std::sin(roll), cp = std::cos(pitch), sp = std::sin(pitch);
  const double cy = std::cos(yaw), sy = std::sin(yaw);
  Eigen::Matrix3d c;
  c << cp * cy, sr * sp * cy - cr * sy, cr * sp * cy + sr * sy,  //
      cp * sy, sr * sp * sy + cr * cy, cr * sp * sy - sr * cy,   //
      -sp, sr * cp, cr * cp;
  return c;
}
inline Eigen::Matrix3d C_nb_of(const dataset::CsvRow& truth) {
  using namespace dataset::truth_col;
  return C_nb(truth.value[roll] * kDeg, truth.value[pitch] * kDeg, truth.value[yaw] * kDeg);
}
}  // namespace ref

inline Eigen::Vector3d triple(const dataset::CsvRow& r, std::size_t first) {
  return {r.value[first], r.value[first + 1], r.value[first + 2]};
}

}  // namespace sinu::test
