// Streaming: reading imu.csv allocates the same number of times for 1 k and
// 200 k rows (buffers are sized once, at open), so memory stays constant
// whatever the file length.
#include <gtest/gtest.h>

#include "firmware/host/dataset/csv_table.hpp"
#include "firmware/host/dataset/imu_csv.hpp"
#include "host_tests/support/alloc_counter.hpp"
#include "host_tests/support/temp_dir.hpp"

using namespace sinu::dataset;

namespace {

void write_rows(const std::string& path, int n) {
  CsvWriter w(kImuSchema);
  set_imu_formats(w);
  ASSERT_TRUE(w.open(path));
  CsvRow r;
  for (int i = 0; i < n; ++i) {
    r.clear(imu_col::count);
    r.set(imu_col::t, 100.0 + 0.025 * i);
    for (std::size_t c = imu_col::ax; c <= imu_col::gz; ++c) r.set(c, 0.001 * i + static_cast<double>(c));
    ASSERT_TRUE(w.write(r));
  }
  ASSERT_TRUE(w.close());
}

std::uint64_t allocations_to_read(const std::string& path, std::size_t expected_rows) {
  sinu::test::AllocationScope scope;
  CsvReader reader(kImuSchema);
  EXPECT_TRUE(reader.open(path));
  CsvRow r;
  while (reader.next(r) == ReadStatus::Row) {
  }
  EXPECT_EQ(reader.rows(), expected_rows);
  return scope.count();
}

}  // namespace

TEST(DatasetAlloc, ReadingAllocatesIndependentlyOfLength) {
  sinu::test::TempDir dir;
  write_rows(dir.file("small.csv"), 1000);
  write_rows(dir.file("large.csv"), 200000);
  const auto small = allocations_to_read(dir.file("small.csv"), 1000);
  const auto large = allocations_to_read(dir.file("large.csv"), 200000);
  EXPECT_EQ(small, large);
  EXPECT_LT(large, 20u) << "open() allocates a handful of buffers; rows allocate nothing";
}

TEST(DatasetAlloc, WritingAllocatesNothingPerRow) {
  sinu::test::TempDir dir;
  CsvWriter w(kImuSchema);
  ASSERT_TRUE(w.open(dir.file("imu.csv")));
  CsvRow r;
  sinu::test::AllocationScope scope;
  for (int i = 0; i < 50000; ++i) {
    r.clear(imu_col::count);
    r.set(imu_col::t, 1.0 + i);
    ASSERT_TRUE(w.write(r));
  }
  EXPECT_EQ(scope.count(), 0u);
  ASSERT_TRUE(w.close());
}
