// imu.csv reading and writing throughput on a 1 M-row file (about 7 hours of
// 40 Hz data). Report: rows/s in the "items_per_second" column.
#include <benchmark/benchmark.h>

#include "firmware/host/dataset/csv_table.hpp"
#include "firmware/host/dataset/imu_csv.hpp"
#include "host_tests/support/temp_dir.hpp"

using namespace sinu::dataset;

namespace {

constexpr int kRows = 1'000'000;

CsvRow sample_row(int i) {
  CsvRow r;
  r.clear(imu_col::count);
  r.set(imu_col::t, 1000.0 + 0.025 * i);
  // Values shaped like a real MEMS IMU at rest, with noise-like digits.
  r.set(imu_col::ax, 0.0123456 + 1e-7 * (i % 997));
  r.set(imu_col::ay, -0.0234567 + 1e-7 * (i % 991));
  r.set(imu_col::az, -9.80665 + 1e-7 * (i % 983));
  r.set(imu_col::gx, 0.00012345 + 1e-9 * (i % 977));
  r.set(imu_col::gy, -0.00023456 + 1e-9 * (i % 971));
  r.set(imu_col::gz, 0.00034567 + 1e-9 * (i % 967));
  if (i % 4 == 0) {
    r.set(imu_col::mx, 21.5);
    r.set(imu_col::my, -3.25);
    r.set(imu_col::mz, 43.0);
  }
  r.set(imu_col::temp, 31.25);
  return r;
}

void write_file(const std::string& path) {
  CsvWriter w(kImuSchema);
  set_imu_formats(w);
  w.open(path);
  for (int i = 0; i < kRows; ++i) w.write(sample_row(i));
  w.close();
}

void BM_ImuCsvRead(benchmark::State& state) {
  sinu::test::TempDir dir;
  const std::string path = dir.file("imu.csv");
  write_file(path);
  for (auto _ : state) {
    CsvReader reader(kImuSchema);
    reader.open(path);
    CsvRow r;
    double sum = 0.0;
    while (reader.next(r) == ReadStatus::Row) sum += r.value[imu_col::az];
    benchmark::DoNotOptimize(sum);
    if (reader.rows() != kRows) state.SkipWithError("row count");
  }
  state.SetItemsProcessed(state.iterations() * kRows);
}
BENCHMARK(BM_ImuCsvRead)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_ImuCsvWrite(benchmark::State& state) {
  sinu::test::TempDir dir;
  for (auto _ : state) write_file(dir.file("imu.csv"));
  state.SetItemsProcessed(state.iterations() * kRows);
}
BENCHMARK(BM_ImuCsvWrite)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace

BENCHMARK_MAIN();
