// Raw recording format: round trip, torn tail, corruption, forward compatibility.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <vector>

#include "hal/recording/recording_reader.hpp"
#include "hal/recording/recording_writer.hpp"
#include "host_tests/support/temp_dir.hpp"

using namespace sinu::hal::rec;

namespace {

// 3 seconds of a 40 Hz IMU with a GPS chunk every 200 ms.
std::size_t write_sample_recording(const std::string& path) {
  RecordingWriter w;
  EXPECT_TRUE(w.open(path)) << w.error();
  const std::array<std::uint8_t, 1> line{0};
  std::array<std::uint8_t, 17> i2c{0x69, 0x2D, 0};
  for (int k = 0; k < 120; ++k) {
    const sinu::hal::TimeNs t = 5'000'000'000 + k * 25'000'000LL;
    EXPECT_TRUE(w.append(Kind::GpioEdge, t, line));
    i2c[3] = static_cast<std::uint8_t>(k);
    EXPECT_TRUE(w.append(Kind::I2cRead, t + 300'000, i2c));
    if (k % 8 == 0) {
      const std::string nmea = "$GPGGA,1*00\r\n";
      std::vector<std::uint8_t> p{0};
      p.insert(p.end(), nmea.begin(), nmea.end());
      EXPECT_TRUE(w.append(Kind::SerialRx, t + 500'000, p));
    }
  }
  EXPECT_TRUE(w.close());
  return static_cast<std::size_t>(w.records());
}

std::vector<char> slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(Recording, WritesAndReadsBackEveryRecord) {
  sinu::test::TempDir dir;
  const std::string path = dir.file("a.raw");
  const std::size_t n = write_sample_recording(path);
  RecordingReader r;
  ASSERT_TRUE(r.open(path)) << r.message();
  Record rec;
  std::size_t edges = 0, reads = 0, rx = 0;
  sinu::hal::TimeNs last = 0;
  while (r.next(rec) == ReadStatus::Record) {
    EXPECT_GE(rec.t_ns, last);
    last = rec.t_ns;
    if (rec.kind == Kind::GpioEdge) ++edges;
    if (rec.kind == Kind::I2cRead) {
      ASSERT_EQ(rec.payload.size(), 17u);
      EXPECT_EQ(rec.payload[3], static_cast<std::uint8_t>(reads));
      ++reads;
    }
    if (rec.kind == Kind::SerialRx) ++rx;
  }
  EXPECT_EQ(r.records(), n);
  EXPECT_EQ(edges, 120u);
  EXPECT_EQ(reads, 120u);
  EXPECT_EQ(rx, 15u);
  EXPECT_EQ(r.next(rec), ReadStatus::End);
  // Compact: 40 Hz edge + 14-byte IMU read is 16 + 32 bytes per sample.
  EXPECT_LT(std::filesystem::file_size(path), 120u * 50u + 15u * 30u);
}

TEST(Recording, TruncatedFileReadsToTheLastWholeRecordAndSaysSo) {
  sinu::test::TempDir dir;
  const std::string path = dir.file("a.raw");
  const std::size_t n = write_sample_recording(path);
  const auto bytes = slurp(path);
  for (const std::size_t cut : {std::size_t{5}, std::size_t{9}}) {  // inside the trailer, inside the header
    const std::string cut_path = dir.file("cut.raw");
    std::ofstream(cut_path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size() - cut));
    RecordingReader r;
    ASSERT_TRUE(r.open(cut_path));
    Record rec;
    ReadStatus s;
    while ((s = r.next(rec)) == ReadStatus::Record) {
    }
    EXPECT_EQ(s, ReadStatus::Truncated);
    EXPECT_EQ(r.records(), n - 1) << "only the torn last record is lost";
    EXPECT_NE(r.message().find("truncated"), std::string::npos) << r.message();
  }
}

TEST(Recording, CorruptRecordStopsWithItsOffset) {
  sinu::test::TempDir dir;
  const std::string path = dir.file("a.raw");
  write_sample_recording(path);
  auto bytes = slurp(path);
  bytes[kFileHeaderSize + 40] ^= 0x10;  // flip a bit inside an early record
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  RecordingReader r;
  ASSERT_TRUE(r.open(path));
  Record rec;
  ReadStatus s;
  while ((s = r.next(rec)) == ReadStatus::Record) {
  }
  EXPECT_EQ(s, ReadStatus::Corrupt);
  EXPECT_NE(r.message().find("CRC mismatch"), std::string::npos) << r.message();
  EXPECT_LT(r.records(), 3u);
}

TEST(Recording, RejectsOtherFilesAndNewerVersions) {
  sinu::test::TempDir dir;
  RecordingReader r;
  EXPECT_FALSE(r.open(dir.write("x.raw", "t,ax,ay\n1,2,3\n")));
  EXPECT_NE(r.message().find("not a sinu raw recording"), std::string::npos);
  const std::string path = dir.file("a.raw");
  write_sample_recording(path);
  auto bytes = slurp(path);
  bytes[8] = static_cast<char>(kVersion + 1);
  std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  EXPECT_FALSE(r.open(path));
  EXPECT_NE(r.message().find("newer"), std::string::npos) << r.message();
  EXPECT_FALSE(r.open(dir.file("missing.raw")));
}

TEST(Recording, SkipsRecordKindsOfANewerWriter) {
  sinu::test::TempDir dir;
  const std::string path = dir.file("a.raw");
  RecordingWriter w;
  ASSERT_TRUE(w.open(path));
  const std::array<std::uint8_t, 2> p{1, 2};
  ASSERT_TRUE(w.append(static_cast<Kind>(200), 1, p));
  ASSERT_TRUE(w.append(Kind::GpioEdge, 2, p));
  ASSERT_TRUE(w.close());
  RecordingReader r;
  ASSERT_TRUE(r.open(path));
  Record rec;
  ASSERT_EQ(r.next(rec), ReadStatus::Record);
  EXPECT_EQ(rec.kind, Kind::GpioEdge);
  EXPECT_EQ(r.unknown_records(), 1u);
}

TEST(Recording, Crc32MatchesTheStandardCheckValue) {
  const std::string check = "123456789";  // CRC-32/ISO-HDLC check value 0xCBF43926
  EXPECT_EQ(crc32({reinterpret_cast<const std::uint8_t*>(check.data()), check.size()}), 0xCBF43926u);
}

TEST(Recording, ACrashLosesAtMostTheLastSecond) {
  sinu::test::TempDir dir;
  const std::string path = dir.file("a.raw");
  RecordingWriter w;
  ASSERT_TRUE(w.open(path));
  const std::array<std::uint8_t, 1> line{0};
  const sinu::hal::TimeNs t0 = 1'000'000'000, period = 25'000'000;
  sinu::hal::TimeNs last = 0;
  for (int k = 0; k < 200; ++k) ASSERT_TRUE(w.append(Kind::GpioEdge, last = t0 + k * period, line));
  // The process "dies" here: whatever is on disk now is all that survives.
  RecordingReader r;
  ASSERT_TRUE(r.open(path));
  Record rec;
  sinu::hal::TimeNs on_disk = 0;
  while (r.next(rec) == ReadStatus::Record) on_disk = rec.t_ns;
  EXPECT_GE(on_disk, last - RecordingWriter::kSyncPeriodNs);
}
