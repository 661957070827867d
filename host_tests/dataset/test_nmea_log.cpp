// gps.nmea: corrupt lines are counted and skipped, never stop the reader.
#include <gtest/gtest.h>

#include "firmware/host/dataset/nmea_log.hpp"
#include "host_tests/support/temp_dir.hpp"

using namespace sinu::dataset;

namespace {
const char* kGga0 = "$GNGGA,193400.50,4005.7976080,N,10508.8468980,W,4,21,,1601.474,M,-21.387,M,,*58";
const char* kRmc0 = "$GNRMC,193400.50,A,4005.7976080,N,10508.8468980,W,0.020,348.69,080725,,,R*78";
const char* kGga1 = "$GNGGA,193400.75,4005.7976080,N,10508.8468980,W,4,21,,1601.476,M,-21.387,M,,*5D";
}  // namespace

TEST(NmeaLog, CorruptLinesAndSentencesAreCountedAndSkipped) {
  sinu::test::TempDir dir;
  std::string text;
  text += std::string("100.000,") + kGga0 + "\n";
  text += std::string("100.001,") + kRmc0 + "\r\n";
  text += "100.002,$GNGGA,193400.50,4005.79*00\n";       // truncated, checksum wrong
  text += "garbage without a comma\n";                  // no arrival time
  text += "abc,$GNGGA,1*00\n";                          // arrival time not a number
  text += std::string("99.000,") + kGga1 + "\n";        // arrival time going backwards
  text += "100.100,$GNGGA,193400.75,4005.7976080,N\n";  // truncated: no checksum
  text += std::string("100.250,") + kGga1 + "\n";
  const auto path = dir.write("gps.nmea", text);
  GpsLogReader r;
  ASSERT_TRUE(r.open(path));
  sinu::drivers::GpsFix fix;
  ASSERT_EQ(r.next(fix), ReadStatus::Row) << r.error().to_string();
  EXPECT_DOUBLE_EQ(fix.arrival_s, 100.0);
  EXPECT_TRUE(fix.has_rmc);
  ASSERT_EQ(r.next(fix), ReadStatus::Row);
  EXPECT_DOUBLE_EQ(fix.arrival_s, 100.25);
  EXPECT_EQ(r.next(fix), ReadStatus::End);
  EXPECT_EQ(r.log().lines(), 8u);
  EXPECT_EQ(r.log().skipped_lines(), 3u);
  EXPECT_EQ(r.counters().bad_checksum, 1u);
  EXPECT_EQ(r.counters().missing_checksum, 1u);
  EXPECT_EQ(r.counters().good, 3u);
  EXPECT_EQ(r.corrupt(), 5u) << "every line is accounted for: 3 good + 5 corrupt = 8";
  EXPECT_EQ(r.log().first_skipped().line, 4u);
  EXPECT_EQ(r.first_corrupt().line, 3u);
}

TEST(NmeaLog, ALineOfGarbageLongerThan4KiBIsCountedNotFatal) {
  sinu::test::TempDir dir;
  const std::string text = std::string("100.000,") + kGga0 + "\n100.001," + std::string(5000, '\x7f') + "\n" +
                           "100.250," + kGga1 + "\n";
  const auto path = dir.write("gps.nmea", text);
  GpsLogReader r;
  ASSERT_TRUE(r.open(path));
  sinu::drivers::GpsFix fix;
  int fixes = 0;
  ReadStatus st;
  while ((st = r.next(fix)) == ReadStatus::Row) ++fixes;
  EXPECT_EQ(st, ReadStatus::End) << r.error().to_string();
  EXPECT_EQ(fixes, 2);
  EXPECT_EQ(r.log().skipped_lines(), 1u);
  EXPECT_EQ(r.log().first_skipped().line, 2u);
}

TEST(NmeaLog, WriterRoundTrip) {
  sinu::test::TempDir dir;
  {
    NmeaLogWriter w;
    ASSERT_TRUE(w.open(dir.file("gps.nmea")));
    ASSERT_TRUE(w.write(1203.4, kGga0));
    ASSERT_TRUE(w.write(1203.401, kRmc0));
    ASSERT_TRUE(w.close());
  }
  NmeaLogReader r;
  ASSERT_TRUE(r.open(dir.file("gps.nmea")));
  NmeaLogLine line;
  ASSERT_EQ(r.next(line), ReadStatus::Row);
  EXPECT_DOUBLE_EQ(line.arrival_s, 1203.4);
  EXPECT_EQ(line.sentence, kGga0);
  ASSERT_EQ(r.next(line), ReadStatus::Row);
  EXPECT_EQ(line.sentence, kRmc0);
  EXPECT_EQ(r.next(line), ReadStatus::End);
}
