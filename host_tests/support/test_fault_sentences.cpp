// The fault injector on hand-written files: hemispheres, a crossing of the
// equator and of 180 deg, other number formats, lower-case checksums, corrupt
// and fix-less sentences, lines without a time; and the garbage generator's
// guarantee checked on many sentences with the project's sentence checker.
#include <gtest/gtest.h>

#include <cctype>
#include <string>

#include "drivers/gps/nmea_parser.hpp"
#include "firmware/host/dataset/csv_table.hpp"
#include "firmware/host/dataset/imu_csv.hpp"
#include "host_tests/sim/sim_test_support.hpp"
#include "host_tests/support/dataset_faults.hpp"
#include "host_tests/support/faults/nmea_garbage.hpp"
#include "host_tests/support/faults/text_lines.hpp"
#include "host_tests/support/nmea_text.hpp"
#include "host_tests/support/temp_dir.hpp"

using namespace sinu;
using namespace sinu::test;

namespace {

std::string lower_checksum(std::string s) {
  for (std::size_t i = s.size() - 2; i < s.size(); ++i) s[i] = static_cast<char>(std::tolower(s[i]));
  return s;
}

struct Sentence {
  const char* arrival;
  std::string text;
};

// 4 minute decimals (0.19 m steps), 5, and the simulator's 6.
const std::vector<Sentence> kSentences = {
    {"10.000", lower_checksum(nmea_with_checksum("GNGLL,3351.1234,S,15112.5670,W,123456.00,A,A"))},
    {"10.010", nmea_with_checksum("GPGGA,123456.00,0000.0020,N,00000.0020,E,1,08,1.0,12.5,M,-3.0,M,,")},
    {"10.020", nmea_with_checksum("GPRMC,123456.00,A,4807.03812,N,17959.99990,E,22.4,084.4,230394,003.1,W")},
    {"10.030", nmea_with_checksum("GPGGA,123456.00,,,,,0,00,99.9,,M,,M,,")},                // no fix
    {"10.040", "$GPRMC,123456.00,A,4807.038,N,01131.000,E,022.4,084.4,230394,003.1,W*00"},  // bad checksum
    {"10.050", nmea_with_checksum("PGRME,15.0,M,45.0,M,25.0,M")},                           // proprietary
    {"10.060", nmea_with_checksum("GPVTG,084.4,T,,M,022.4,N,041.5,K")},
};

/// A dataset folder holding kSentences (and a line without a time, and no
/// LF after the last line) and a small imu.csv with one empty accel field.
void write_dataset(const TempDir& dir) {
  std::string gps = "no time on this line\n";
  for (const auto& s : kSentences) gps += std::string(s.arrival) + "," + s.text + "\n";
  gps.pop_back();
  dir.write("gps.nmea", gps);
  dir.write("imu.csv",
            "t,ax,ay,az,gx,gy,gz,mx,my,mz,temp\n"
            "10.000,0.1,,-9.81,0.01,0.02,0.03,20,0,40,25\n"
            "10.025,1e-1,0.2,-9.80665,+0.01,0.02,0.03,,,,25\n");
}

std::string line_of(const std::string& path, std::size_t index) {
  return faults::split_lines(read_file(path)).at(index).text;
}

drivers::NmeaMessage parse(const std::string& sentence) {
  drivers::NmeaParser parser;
  drivers::NmeaMessage m;
  EXPECT_EQ(parser.parse(sentence, m), drivers::ParseResult::Message) << sentence << ": " << parser.last_error();
  return m;
}

}  // namespace

TEST(FaultSentences, JumpHandlesHemispheresCrossingsAndFormats) {
  TempDir src, dst;
  write_dataset(src);
  const std::array<double, 3> offset{-100.0, -500.0, 2.0};
  const auto effects = inject_faults(src.path(), dst.path(), {GnssPositionJump{10.0, 0.1, offset}});
  EXPECT_EQ(effects.at(0).changed, 3u) << "GLL, GGA and the good RMC";
  const std::string out = dst.file("gps.nmea");
  const auto in_lines = faults::split_lines(read_file(src.file("gps.nmea")));
  const auto out_lines = faults::split_lines(read_file(out));
  ASSERT_EQ(out_lines.size(), in_lines.size());
  EXPECT_EQ(out_lines.back().eol, "") << "still no LF after the last line";
  for (std::size_t i : {0u, 4u, 5u, 6u, 7u}) EXPECT_EQ(out_lines[i].text, in_lines[i].text) << "line " << i + 1;

  auto sentence = [&](std::size_t i) { return out_lines[i].text.substr(out_lines[i].text.find(',') + 1); };
  auto north_east = [](double lat0, double lon0, double lat1, double lon1, double& n, double& e) {
    double dlon = lon1 - lon0;
    if (dlon > 180.0) dlon -= 360.0;
    if (dlon < -180.0) dlon += 360.0;
    n = (lat1 - lat0) * kDeg * ref::r_meridian(lat0 * kDeg);
    e = dlon * kDeg * ref::r_transverse(lat0 * kDeg) * std::cos(lat0 * kDeg);
  };
  // Tolerances: half a step of the last minute decimal, 1852 m per minute.
  {  // GLL, southern and western hemisphere, 4 decimals, lower-case checksum kept.
    const std::string s = sentence(1);
    EXPECT_EQ(drivers::check_sentence(s), drivers::SentenceCheck::Ok) << s;
    auto upper_hex = [](const std::string& x) { return x.find_first_of("ABCDEF", x.size() - 2) != std::string::npos; };
    auto lower_hex = [](const std::string& x) { return x.find_first_of("abcdef", x.size() - 2) != std::string::npos; };
    ASSERT_TRUE(lower_hex(kSentences[0].text)) << kSentences[0].text;
    EXPECT_FALSE(upper_hex(s)) << s << ": the checksum stays in lower case";
    EXPECT_EQ(s.substr(0, 8), "$GNGLL,3");
    const auto a = std::get<drivers::GllMessage>(parse(s)),
               b = std::get<drivers::GllMessage>(parse(kSentences[0].text));
    double n = 0, e = 0;
    north_east(*b.lat_deg, *b.lon_deg, *a.lat_deg, *a.lon_deg, n, e);
    EXPECT_NEAR(n, offset[0], 0.5e-4 * 1852.0);
    EXPECT_NEAR(e, offset[1], 0.5e-4 * 1852.0);
    EXPECT_EQ(a.utc_ms, b.utc_ms);
    EXPECT_EQ(s.find(",S,"), 16u) << s << ": 4 decimals and the hemisphere kept";
  }
  {  // GGA 0.0020' N 0.0020' E (3.7 m, 3.7 m) moved 100 m south, 500 m west: S and W.
    // At the equator a minute of latitude is 1842.9 m, of longitude 1855.3 m:
    // 0.0020 - 100 / 1842.9 = -0.05226', 0.0020 - 500 / 1855.3 = -0.26749'.
    const std::string s = sentence(2);
    EXPECT_NE(s.find(",0000.0523,S,00000.2675,W,"), std::string::npos) << s;
    const auto a = std::get<drivers::GgaMessage>(parse(s));
    EXPECT_DOUBLE_EQ(*a.alt_msl_m, 10.5) << "12.5 m lowered by 2 m, one decimal";
    EXPECT_NE(s.find(",10.5,M,-3.0,M,"), std::string::npos) << s;
  }
  {  // RMC at 179 59.9999' E moved 500 m west stays east; speed and course text untouched.
    const std::string s = sentence(3);
    const auto a = std::get<drivers::RmcMessage>(parse(s)),
               b = std::get<drivers::RmcMessage>(parse(kSentences[2].text));
    double n = 0, e = 0;
    north_east(*b.lat_deg, *b.lon_deg, *a.lat_deg, *a.lon_deg, n, e);
    EXPECT_NEAR(n, offset[0], 0.5e-5 * 1852.0);
    EXPECT_NEAR(e, offset[1], 0.5e-5 * 1852.0);
    EXPECT_NE(s.find(",E,22.4,084.4,230394,003.1,W*"), std::string::npos) << s;
  }
  // 500 m east from there crosses 180 deg: the longitude wraps to the west.
  TempDir east;
  inject_faults(src.path(), east.path(), {GnssPositionJump{10.02, 0.001, {0.0, 500.0, 0.0}}});
  const std::string s = line_of(east.file("gps.nmea"), 3);
  const auto a = std::get<drivers::RmcMessage>(parse(s.substr(s.find(',') + 1)));
  EXPECT_NE(s.find(",4807.03812,N,17959."), std::string::npos) << "north untouched: " << s;
  EXPECT_NE(s.find(",W,22.4,"), std::string::npos) << s;
  EXPECT_NEAR(*a.lon_deg,
              -180.0 + (500.0 / (ref::r_transverse(48.1173 * kDeg) * std::cos(48.1173 * kDeg)) / kDeg - 0.0001 / 60.0),
              1e-6);
}

TEST(FaultSentences, ClipAndMagKeepEmptyFieldsAndOtherNumberForms) {
  TempDir src, dst;
  write_dataset(src);
  ImuClip clip;
  clip.start_s = 0.0;
  clip.duration_s = 100.0;
  clip.accel_full_scale_m_s2 = 16.0;
  clip.accel_direction = {-1, 1, 0};
  inject_faults(src.path(), dst.path(), {clip, ImuDropMagFirstRows{5}});
  const auto lines = faults::split_lines(read_file(dst.file("imu.csv")));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].text, "t,ax,ay,az,gx,gy,gz,mx,my,mz,temp");
  EXPECT_EQ(lines[1].text, "10.000,-16,,-9.81,0.01,0.02,0.03,,,,25") << "the empty ay stays empty";
  EXPECT_EQ(lines[2].text, "10.025,-16,16,-9.80665,+0.01,0.02,0.03,,,,25") << "other forms kept byte for byte";
  dataset::CsvReader r(dataset::kImuSchema);
  ASSERT_TRUE(r.open(dst.file("imu.csv"))) << r.error().to_string();
  dataset::CsvRow row;
  EXPECT_EQ(r.next(row), dataset::ReadStatus::Row);
  EXPECT_EQ(r.next(row), dataset::ReadStatus::Row);
  EXPECT_EQ(r.next(row), dataset::ReadStatus::End) << r.error().to_string();
}

TEST(FaultSentences, GarbageNeverPassesTheProjectsSentenceCheck) {
  // Originals of every shape: good sentences, the simulator's corrupt kinds,
  // an empty one, one with a CR inside, one with two '*'.
  std::vector<std::string> originals;
  for (const auto& s : kSentences) originals.push_back(s.text);
  originals.insert(originals.end(), {"", "$", "*", "$GPGGA,1\r2,3*4F", "$GPGGA,1*2*3F", "\x01\x02", "$GPZDA"});
  faults::GarbageGenerator garbage(99);
  for (int i = 0; i < 20000; ++i) {
    const std::string& o = originals[static_cast<std::size_t>(i) % originals.size()];
    const std::string g = garbage.next(o);
    ASSERT_NE(drivers::check_sentence(g), drivers::SentenceCheck::Ok) << g;
    ASSERT_EQ(g.find_first_of("\r\n"), std::string::npos);
    ASSERT_LE(g.size(), faults::kMaxGarbageBytes);
  }
}
