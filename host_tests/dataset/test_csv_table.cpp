// imu.csv / truth.csv: round trip and every malformed case of the contract.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <string>

#include "firmware/host/dataset/csv_table.hpp"
#include "firmware/host/dataset/imu_csv.hpp"
#include "firmware/host/dataset/truth_csv.hpp"
#include "host_tests/support/temp_dir.hpp"

using namespace sinu::dataset;

namespace {

const std::string kHeader = "t,ax,ay,az,gx,gy,gz,mx,my,mz,temp\n";

/// Reads the whole file; returns the error (empty message if it read cleanly).
Diagnostic read_all(const std::string& path, std::size_t* rows = nullptr) {
  CsvReader reader(kImuSchema);
  if (!reader.open(path)) return reader.error();
  CsvRow row;
  ReadStatus st;
  while ((st = reader.next(row)) == ReadStatus::Row) {
  }
  if (rows) *rows = reader.rows();
  return st == ReadStatus::Error ? reader.error() : Diagnostic{};
}

}  // namespace

TEST(CsvTable, RoundTripKeepsValuesExactlyAndEmptyFieldsEmpty) {
  sinu::test::TempDir dir;
  std::mt19937_64 rng(42);
  std::normal_distribution<double> n(0.0, 3.0);
  std::vector<CsvRow> written;
  {
    CsvWriter w(kImuSchema);  // shortest round-trip format: exact
    ASSERT_TRUE(w.open(dir.file("imu.csv")));
    double t = 1234.5;
    for (int i = 0; i < 1000; ++i) {
      CsvRow r;
      r.clear(imu_col::count);
      r.set(imu_col::t, t += 0.025);
      for (std::size_t c = imu_col::ax; c <= imu_col::gz; ++c) r.set(c, n(rng));
      if (i % 4 == 0)  // magnetometer at a quarter of the IMU rate
        for (std::size_t c = imu_col::mx; c <= imu_col::mz; ++c) r.set(c, 40.0 * n(rng));
      if (i % 10 == 0) r.set(imu_col::temp, 25.0 + n(rng));
      ASSERT_TRUE(w.write(r));
      written.push_back(r);
    }
    ASSERT_TRUE(w.close());
  }
  CsvReader reader(kImuSchema);
  ASSERT_TRUE(reader.open(dir.file("imu.csv"))) << reader.error().to_string();
  CsvRow r;
  for (const CsvRow& expected : written) {
    ASSERT_EQ(reader.next(r), ReadStatus::Row) << reader.error().to_string();
    ASSERT_EQ(r.present, expected.present);
    for (std::size_t c = 0; c < imu_col::count; ++c) {
      if (expected.has(c)) ASSERT_EQ(r.value[c], expected.value[c]);
      else ASSERT_TRUE(std::isnan(r.value[c])) << "an empty field is no measurement, never zero";
    }
  }
  EXPECT_EQ(reader.next(r), ReadStatus::End);
}

TEST(CsvTable, ProjectFormatsRoundTripWithinTheirStatedResolution) {
  sinu::test::TempDir dir;
  CsvWriter w(kTruthSchema);
  set_truth_formats(w);
  ASSERT_TRUE(w.open(dir.file("truth.csv")));
  CsvRow r;
  r.clear(truth_col::count);
  const double vals[] = {100000.123456789, 40.123456789123, -105.98765432198, 1580.12345, 40.00004, -1.5, 0.25,
                         1.23456789, -2.5, 179.9999999};
  for (std::size_t c = 0; c < truth_col::count; ++c) r.set(c, vals[c]);
  ASSERT_TRUE(w.write(r));
  ASSERT_TRUE(w.close());
  CsvReader reader(kTruthSchema);
  ASSERT_TRUE(reader.open(dir.file("truth.csv")));
  CsvRow back;
  ASSERT_EQ(reader.next(back), ReadStatus::Row);
  EXPECT_NEAR(back.value[truth_col::t], vals[0], 0.5e-6);     // fixed 6 decimals
  EXPECT_NEAR(back.value[truth_col::lat], vals[1], 0.5e-9);   // fixed 9 decimals = 0.1 mm
  EXPECT_NEAR(back.value[truth_col::h], vals[3], 0.5e-4);     // fixed 4 decimals
  EXPECT_NEAR(back.value[truth_col::yaw], vals[9], 0.5e-6);   // fixed 6 decimals
}

TEST(CsvTable, AcceptsEveryNumberFormStrtodAccepts) {
  sinu::test::TempDir dir;
  const auto p = dir.write("imu.csv", kHeader + "1,+1.5,0x1p-2,1e3,-0, .5,5.,1E-3,,,\r\n");
  CsvReader reader(kImuSchema);
  ASSERT_TRUE(reader.open(p));
  CsvRow r;
  ASSERT_EQ(reader.next(r), ReadStatus::Row) << reader.error().to_string();
  EXPECT_EQ(r.value[imu_col::ax], 1.5);
  EXPECT_EQ(r.value[imu_col::ay], 0.25);
  EXPECT_EQ(r.value[imu_col::az], 1000.0);
  EXPECT_EQ(r.value[imu_col::gy], 0.5);  // leading blank, as strtod skips it
  EXPECT_EQ(r.value[imu_col::gz], 5.0);
  EXPECT_EQ(r.value[imu_col::mx], 1e-3);
  EXPECT_FALSE(r.has(imu_col::my));
}

struct MalformedCase {
  const char* name;
  std::string text;
  std::size_t line, column;
  const char* message_part;
};

void PrintTo(const MalformedCase& c, std::ostream* os) { *os << c.name; }

class CsvMalformed : public ::testing::TestWithParam<MalformedCase> {};

TEST_P(CsvMalformed, NamesFileLineColumnAndField) {
  const MalformedCase& c = GetParam();
  sinu::test::TempDir dir;
  const auto path = dir.write("imu.csv", c.text);
  const Diagnostic d = read_all(path);
  ASSERT_FALSE(d.message.empty()) << c.name << ": the bad input was accepted";
  EXPECT_EQ(d.file, path);
  EXPECT_EQ(d.line, c.line) << d.to_string();
  EXPECT_EQ(d.column, c.column) << d.to_string();
  EXPECT_NE(d.message.find(c.message_part), std::string::npos) << d.to_string();
}

const std::string kGood = "10.000,0,0,-9.8,0,0,0,,,,25\n";

INSTANTIATE_TEST_SUITE_P(
    Contract, CsvMalformed,
    ::testing::Values(
        MalformedCase{"EmptyFile", "", 0, 0, "empty file"},
        MalformedCase{"MissingHeader", "10.0,0,0,-9.8,0,0,0,,,,25\n", 1, 1, "header"},
        MalformedCase{"WrongHeaderColumn", "t,ax,ay,az,gx,gy,gz,mx,my,mz,tmp\n", 1, 31, "header"},
        MalformedCase{"TooFewColumns", kHeader + kGood + "10.025,0,0,-9.8,0,0,0,,,\n", 3, 25, "expected 11 fields, found 10"},
        MalformedCase{"TooManyColumns", kHeader + kGood + "10.025,0,0,-9.8,0,0,0,,,,25,7\n", 3, 28, "found 12"},
        MalformedCase{"NonNumeric", kHeader + kGood + "10.025,0,0,-9.8,0,abc,0,,,,25\n", 3, 19, "field 'gy': not a number 'abc'"},
        MalformedCase{"TrailingGarbage", kHeader + "10.025,0,0,-9.8x,0,0,0,,,,25\n", 2, 12, "field 'az': not a number"},
        MalformedCase{"NaN", kHeader + "10.025,0,nan,-9.8,0,0,0,,,,25\n", 2, 10, "field 'ay': not finite"},
        MalformedCase{"Infinity", kHeader + "10.025,0,0,-9.8,0,0,0,,,,-inf\n", 2, 26, "field 'temp': not finite"},
        MalformedCase{"Overflow", kHeader + "10.025,1e999,0,-9.8,0,0,0,,,,25\n", 2, 8, "field 'ax': not finite"},
        MalformedCase{"TimeRepeated", kHeader + kGood + kGood, 3, 1, "time not increasing"},
        MalformedCase{"TimeBackwards", kHeader + kGood + "9.975,0,0,-9.8,0,0,0,,,,25\n", 3, 1, "time not increasing"},
        MalformedCase{"TimeMissing", kHeader + ",0,0,-9.8,0,0,0,,,,25\n", 2, 1, "field 't': empty"},
        MalformedCase{"BlankLine", kHeader + kGood + "\n", 3, 1, "expected 11 fields, found 1"}),
    [](const auto& param_info) { return std::string(param_info.param.name); });

/// `n` rows at `period` from t0, with `gap_after` (row index) followed by an extra `gap` of time.
std::string imu_rows(double t0, double period, int n, int gap_after = -1, double gap = 0.0) {
  std::string text = kHeader;
  double t = t0;
  for (int i = 0; i < n; ++i) {
    char line[96];
    std::snprintf(line, sizeof line, "%.6f,0,0,-9.8,0,0,0,,,,25\n", t);
    text += line;
    t += period + (i == gap_after ? gap : 0.0);
  }
  return text;
}

// A converter that wrote t in milliseconds: every row is valid, and the
// replay reset 2591 times over a 5-minute flight (the IMU ran at "0.04 Hz").
TEST(CsvTable, TimeInMillisecondsIsAnErrorSayingSo) {
  sinu::test::TempDir dir;
  const Diagnostic d = read_all(dir.write("imu.csv", imu_rows(667788.0, 25.0, 40)));
  EXPECT_EQ(d.line, 22u) << d.to_string();  // the 21st row: its 20 intervals judged
  EXPECT_EQ(d.column, 1u);
  EXPECT_NE(d.message.find("median 25 s per row"), std::string::npos) << d.to_string();
  EXPECT_NE(d.message.find("t must be seconds"), std::string::npos) << d.to_string();
}

// Seconds with a 3-s gap among the first rows, or a 10-Hz IMU: read as they are.
TEST(CsvTable, TimeInSecondsWithAGapOrASlowImuIsRead) {
  sinu::test::TempDir dir;
  std::size_t rows = 0;
  EXPECT_TRUE(read_all(dir.write("gap.csv", imu_rows(100.0, 0.025, 40, 5, 3.0)), &rows).message.empty());
  EXPECT_EQ(rows, 40u);
  EXPECT_TRUE(read_all(dir.write("slow.csv", imu_rows(100.0, 0.1, 40)), &rows).message.empty());
}

TEST(CsvTable, MissingFileIsAnErrorNamingIt) {
  const Diagnostic d = read_all("/nonexistent/imu.csv");
  EXPECT_EQ(d.file, "/nonexistent/imu.csv");
  EXPECT_NE(d.message.find("cannot open"), std::string::npos);
}

TEST(CsvTable, DiagnosticFormatsAsFileLineColumn) {
  EXPECT_EQ((Diagnostic{"d/imu.csv", 17, 23, "field 'gz': not a number 'x'"}.to_string()),
            "d/imu.csv:17:23: field 'gz': not a number 'x'");
}

TEST(CsvTable, ParseDoubleAgreesBitForBitWithStrtod) {
  // The contract says numbers are whatever C's strtod accepts; our fast path
  // must give strtod's exact double, including near rounding boundaries.
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mant(-10.0, 10.0);
  std::uniform_int_distribution<int> exp10(-30, 30), prec(1, 20);
  char buf[64];
  for (int i = 0; i < 200000; ++i) {
    const double x = mant(rng) * std::pow(10.0, exp10(rng));
    const int p = prec(rng);
    std::snprintf(buf, sizeof buf, (i % 3 == 0) ? "%.*e" : (i % 3 == 1) ? "%.*g" : "%.*f", p, x);
    double ours = 0.0;
    ASSERT_TRUE(parse_double(buf, ours)) << buf;
    const double ref = std::strtod(buf, nullptr);
    ASSERT_EQ(std::memcmp(&ours, &ref, sizeof ref), 0) << buf;
  }
}
