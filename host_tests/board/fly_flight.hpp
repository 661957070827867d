#pragma once
// Simulated flights for the `sinu fly --emulate` tests, and the comparisons
// they need: a flight as the chip sees it (DIR -> RAW -> DIR2: accelerometer
// and gyro quantised to the configured full scales' LSBs, what the
// emulator's registers hold and so what fly reads), a hermetic sinu.toml, and
// nav.csv files read back as numbers.
#include <string>
#include <vector>

#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {

struct FlyFlight {
  std::string dir;        // as simulated (truth.csv)
  std::string quantised;  // through the chip's registers and back
  double t0_s = 0.0;      // first imu.csv time
};

/// `seconds` of the simulator's default UAV flight with `seed`, in `tmp`.
FlyFlight make_fly_flight(const TempDir& tmp, const std::string& name, int seconds, int seed);

/// A sinu.toml with no calibration and the navigation log at `log`, plus `extra` TOML.
std::string write_fly_config(const TempDir& tmp, const std::string& name, const std::string& extra = "");

struct CsvNumbers {
  std::string header;
  std::vector<std::vector<double>> rows;  // empty fields as NaN
};
CsvNumbers read_csv_numbers(const std::string& path);

/// The largest |a - b| over rows of `a` with t <= t_max that `b` also has
/// (same t), and how many such rows; NaN fields must be NaN in both (else infinite).
struct CsvDifference {
  double max_abs = 0.0;
  std::size_t rows = 0;
};
CsvDifference compare_rows(const CsvNumbers& a, const CsvNumbers& b, double t_max);

}  // namespace sinu::test
