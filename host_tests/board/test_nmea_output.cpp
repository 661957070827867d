// The NMEA output's text: exact sentences and checksums, hemispheres, a
// solution without a fix, UTC at midnight, the error ellipse, extremes that
// must not overflow a sentence, the output rate, and no allocation.
// (gpsd's decoder: test_nmea_gpsdecode.cpp; a real pty: test_nmea_output_pty.cpp.)
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "estimator/nav/nav_health.hpp"
#include "firmware/board/outputs/error_ellipse.hpp"
#include "firmware/board/outputs/nmea_output.hpp"
#include "host_tests/board/nmea_output_cases.hpp"
#include "host_tests/support/alloc_counter.hpp"
#include "host_tests/support/nmea_text.hpp"

namespace {

using sinu::board::NavSolution;
using sinu::board::NmeaTalker;
namespace t = sinu::test;

std::string line(const std::string& body) { return t::nmea_with_checksum(body) + "\r\n"; }

template <auto Writer>
std::string text(const NavSolution& n, NmeaTalker talker = NmeaTalker::GP) {
  std::array<char, sinu::board::kNmeaSentenceMax> buf{};
  return {buf.data(), Writer(n, talker, buf)};
}
std::string epoch(const NavSolution& n, NmeaTalker talker = NmeaTalker::GP) {
  std::array<char, sinu::board::kNmeaEpochMax> buf{};
  return {buf.data(), sinu::board::write_nmea_epoch(n, talker, buf)};
}

/// Collects what the output writes; fails on request. Reserved up front so
/// that taking bytes never allocates during the allocation test.
class CapturePort final : public sinu::hal::SerialPort {
 public:
  CapturePort() { bytes.reserve(1 << 16); }
  bool set_baud(std::uint32_t) override { return true; }
  sinu::hal::SerialResult read(std::span<std::uint8_t>, sinu::hal::TimeNs) override { return {}; }
  sinu::hal::SerialResult write(std::span<const std::uint8_t> b) override {
    ++writes;
    if (fail) return {sinu::hal::SerialStatus::Error, 0};
    bytes.append(reinterpret_cast<const char*>(b.data()), b.size());
    return {sinu::hal::SerialStatus::Ok, b.size()};
  }
  std::string bytes;
  int writes = 0;
  bool fail = false;
};

NavSolution north_east() {
  return t::solution(30.408539123, 114.352057601, t::utc_ms(2026, 3, 22, 10, 15, 20, 123), {10.1, 3.2, -0.4});
}

}  // namespace

TEST(NmeaOutput, ExactSentencesAndChecksums) {
  const NavSolution n = north_east();
  // 30.408539123 deg = 30 deg 24.51234738 min; 114.352057601 deg = 114 deg 21.12345606 min.
  // 512.3456789 - (-28.7654321) = 541.111111 m MSL; |v| = 10.5948 m/s = 20.5948 kn; course 17.58 deg.
  EXPECT_EQ(text<sinu::board::write_rmc>(n),
            line("GPRMC,101520.123,A,3024.512347,N,11421.123456,E,20.595,17.58,220326,,,A"));
  EXPECT_EQ(text<sinu::board::write_gga>(n),
            line("GPGGA,101520.123,3024.512347,N,11421.123456,E,1,14,0.73,541.111,M,-28.765,M,,"));
  // P_NE = [[0.0912345, 0.0234567], [0.0234567, 0.0456789]]: axes 0.3180, 0.1891 m at 22.92 deg;
  // rms sqrt(0.0912345 + 0.0456789 + 0.2598765) = 0.6299 m.
  EXPECT_EQ(text<sinu::board::write_gst>(n), line("GPGST,101520.123,0.630,0.318,0.189,22.9,0.302,0.214,0.510"));
  EXPECT_EQ(epoch(n), text<sinu::board::write_rmc>(n) + text<sinu::board::write_gga>(n) +
                          text<sinu::board::write_gst>(n));
}

TEST(NmeaOutput, TalkerGn) {
  const std::string e = epoch(north_east(), NmeaTalker::GN);
  EXPECT_EQ(e.rfind("$GNRMC,", 0), 0u);
  EXPECT_NE(e.find("\r\n$GNGGA,"), std::string::npos);
  EXPECT_NE(e.find("\r\n$GNGST,"), std::string::npos);
  NmeaTalker talker = NmeaTalker::GP;
  EXPECT_TRUE(sinu::board::parse_talker("GN", talker));
  EXPECT_EQ(talker, NmeaTalker::GN);
  EXPECT_FALSE(sinu::board::parse_talker("GL", talker));
}

TEST(NmeaOutput, SouthernAndWesternHemispheres) {
  const NavSolution n = t::solution(-33.856789123, -70.661234567, t::utc_ms(2026, 3, 22, 10, 15, 20, 0),
                                    {-3.2, -10.1, 0.5});
  EXPECT_EQ(text<sinu::board::write_gga>(n),
            line("GPGGA,101520.000,3351.407347,S,07039.674074,W,1,14,0.73,541.111,M,-28.765,M,,"));
  const std::string rmc = text<sinu::board::write_rmc>(n);
  EXPECT_NE(rmc.find(",3351.407347,S,07039.674074,W,20.595,252.42,"), std::string::npos) << rmc;
}

TEST(NmeaOutput, EveryCaseDecodesThroughTheProjectParser) {
  std::string bytes;
  const auto cases = t::hemisphere_cases();
  for (const auto& n : cases) bytes += epoch(n);
  const t::Decoded d = t::decode_with_project_parser(bytes);
  EXPECT_EQ(d.counters.sentences.good, 3 * cases.size());
  EXPECT_EQ(d.counters.sentences.corrupt(), 0u);
  ASSERT_EQ(d.fixes.size(), cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    SCOPED_TRACE(i);
    t::expect_fix_matches(d.fixes[i], cases[i]);
  }
}

TEST(NmeaOutput, NotAlignedIsStatusVQualityZeroWithEmptyFields) {
  NavSolution n = north_east();
  n.aligned = false;
  n.flags = 0;
  EXPECT_EQ(text<sinu::board::write_rmc>(n), line("GPRMC,101520.123,V,,,,,,,220326,,,N"));
  EXPECT_EQ(text<sinu::board::write_gga>(n), line("GPGGA,101520.123,,,,,0,14,0.73,,M,,M,,"));
  EXPECT_EQ(text<sinu::board::write_gst>(n), line("GPGST,101520.123,,,,,,,"));
  const t::Decoded d = t::decode_with_project_parser(epoch(n));
  ASSERT_EQ(d.fixes.size(), 1u);
  EXPECT_FALSE(d.fixes[0].has_position());
  EXPECT_EQ(d.fixes[0].quality, 0);
  EXPECT_FALSE(d.fixes[0].rmc_valid);
  EXPECT_EQ(d.counters.sentences.corrupt(), 0u);
}

TEST(NmeaOutput, LostIsNoFixEither) {
  NavSolution n = north_east();
  n.flags |= sinu::est::nav_flag::kLost;
  EXPECT_FALSE(sinu::board::nmea_fix_valid(n));
  EXPECT_EQ(text<sinu::board::write_gga>(n), line("GPGGA,101520.123,,,,,0,14,0.73,,M,,M,,"));
  EXPECT_EQ(text<sinu::board::write_rmc>(n), line("GPRMC,101520.123,V,,,,,,,220326,,,N"));
  n.flags = sinu::est::nav_flag::kAligned | sinu::est::nav_flag::kGnssTimeout;  // dead reckoning: still a fix
  EXPECT_TRUE(sinu::board::nmea_fix_valid(n));
}

TEST(NmeaOutput, WithoutUtcTimeAndDateAreEmpty) {
  NavSolution n = north_east();
  n.has_utc = false;
  EXPECT_EQ(text<sinu::board::write_rmc>(n).rfind("$GPRMC,,A,3024.512347,N,", 0), 0u);
  EXPECT_NE(text<sinu::board::write_rmc>(n).find(",17.58,,,,A*"), std::string::npos);
}

TEST(NmeaOutput, UtcRolloverAtMidnightChangesTheDate) {
  // 31 Dec 2025 23:59:59.900, then 200 ms later: 1 Jan 2026 00:00:00.100.
  NavSolution a = north_east();
  a.utc_ms = t::utc_ms(2025, 12, 31, 23, 59, 59, 900);
  NavSolution b = a;
  b.utc_ms += 200;
  EXPECT_NE(text<sinu::board::write_rmc>(a).find("RMC,235959.900,A,"), std::string::npos);
  EXPECT_NE(text<sinu::board::write_rmc>(a).find(",311225,,,A*"), std::string::npos);
  EXPECT_NE(text<sinu::board::write_rmc>(b).find("RMC,000000.100,A,"), std::string::npos);
  EXPECT_NE(text<sinu::board::write_rmc>(b).find(",010126,,,A*"), std::string::npos);
  const t::Decoded d = t::decode_with_project_parser(epoch(a) + epoch(b));
  ASSERT_EQ(d.fixes.size(), 2u);
  t::expect_fix_matches(d.fixes[0], a);
  t::expect_fix_matches(d.fixes[1], b);
  EXPECT_EQ(d.fixes[0].date, (sinu::drivers::UtcDate{2025, 12, 31}));
  EXPECT_EQ(d.fixes[1].date, (sinu::drivers::UtcDate{2026, 1, 1}));
  EXPECT_EQ(d.fixes[1].utc_ms, 100);
}

TEST(NmeaOutput, CourseJustBelow360IsWrittenAsZero) {
  const NavSolution n = t::solution(10.0, 10.0, t::utc_ms(2026, 1, 1, 0, 0, 0, 0), {25.0, -0.0001, 0.0});
  EXPECT_NE(text<sinu::board::write_rmc>(n).find(",48.596,0.00,"), std::string::npos) << text<sinu::board::write_rmc>(n);
}

TEST(ErrorEllipse, AgreesWithAnEigenDecomposition) {
  for (const double deg : {0.0, 22.5, 45.0, 90.0, 135.0, 179.0}) {
    SCOPED_TRACE(deg);
    const double a = deg * 3.14159265358979323846 / 180.0;
    const Eigen::Matrix2d R{{std::cos(a), -std::sin(a)}, {std::sin(a), std::cos(a)}};
    const Eigen::Matrix2d P = R * Eigen::Vector2d(4.0, 0.25).asDiagonal() * R.transpose();  // axes 2 m and 0.5 m
    const auto e = sinu::board::horizontal_error_ellipse(P(0, 0), P(0, 1), P(1, 1));
    EXPECT_NEAR(e.semi_major_m, 2.0, 1e-12);
    EXPECT_NEAR(e.semi_minor_m, 0.5, 1e-12);
    EXPECT_NEAR(e.orientation_deg, deg, 1e-9);
  }
  const auto circle = sinu::board::horizontal_error_ellipse(1.0, 0.0, 1.0);
  EXPECT_EQ(circle.orientation_deg, 0.0);
  EXPECT_EQ(circle.semi_major_m, 1.0);
}

TEST(NmeaOutput, ExtremesAndNonFiniteValuesNeverOverflowASentence) {
  NavSolution n = t::solution(-89.999999999, -179.999999999, t::utc_ms(2026, 12, 31, 23, 59, 59, 999),
                              {-9999.0, -9999.0, 0.0});
  n.h_ellipsoid_m = -99000.0;
  n.geoid_sep_m = -999.0;
  n.P_nav.block<3, 3>(0, 0) = Eigen::Matrix3d::Identity() * 9.9e9;
  n.satellites = 150;
  n.hdop = 99.99;
  const std::string longest = text<sinu::board::write_gga>(n);
  EXPECT_LE(longest.size(), 88u) << longest;
  EXPECT_EQ(t::decode_with_project_parser(epoch(n)).counters.sentences.corrupt(), 0u);
  // Diverged numbers are empty fields, not a cut sentence.
  n.h_ellipsoid_m = std::numeric_limits<double>::quiet_NaN();
  n.v_ned_m_s.x() = std::numeric_limits<double>::infinity();
  n.P_nav(0, 0) = 1e300;
  n.hdop = 1e6;
  const std::string e = epoch(n);
  EXPECT_EQ(t::decode_with_project_parser(e).counters.sentences.corrupt(), 0u) << e;
  EXPECT_NE(e.find(",1,99,,,M,-999.000,M,,*"), std::string::npos) << e;
}

TEST(NmeaOutput, WritesAtTheConfiguredRate) {
  CapturePort port;
  sinu::board::NmeaOutput out(port, {NmeaTalker::GP, 5.0});
  NavSolution n = north_east();
  for (int i = 0; i < 80; ++i) {  // 2 s of 40 Hz solutions
    n.t_s = 100.0 + i * 0.025;
    EXPECT_TRUE(out.offer(n));
  }
  EXPECT_EQ(out.counters().epochs, 10u);  // at 100.0, 100.2, ..., 101.8
  EXPECT_EQ(port.writes, 10);             // one write per epoch
  EXPECT_EQ(out.counters().bytes, port.bytes.size());
  EXPECT_EQ(port.bytes.substr(0, epoch(n).size()), epoch(n));
  n.t_s = 50.0;  // a new run: written at once
  EXPECT_TRUE(out.offer(n));
  EXPECT_EQ(out.counters().epochs, 11u);
  port.fail = true;
  n.t_s = 50.2;
  EXPECT_FALSE(out.offer(n));
  EXPECT_EQ(out.counters().write_errors, 1u);
}

TEST(NmeaOutput, NoAllocationPerSentence) {
  CapturePort port;
  sinu::board::NmeaOutput out(port, {NmeaTalker::GN, 10.0});
  std::array<char, sinu::board::kNmeaEpochMax> buf{};
  const auto cases = t::hemisphere_cases();
  NavSolution not_aligned = cases[0];
  not_aligned.aligned = false;
  bool all_written = true;
  std::size_t total = 0;
  t::AllocationScope scope;
  for (int i = 0; i < 200; ++i) {
    NavSolution n = i % 7 == 0 ? not_aligned : cases[static_cast<std::size_t>(i) % cases.size()];
    n.t_s = i * 0.1;
    total += sinu::board::write_gga(n, NmeaTalker::GP, buf);
    total += sinu::board::write_rmc(n, NmeaTalker::GP, buf);
    total += sinu::board::write_gst(n, NmeaTalker::GP, buf);
    total += sinu::board::write_nmea_epoch(n, NmeaTalker::GP, buf);
    all_written = out.offer(n) && all_written;
  }
  EXPECT_EQ(scope.count(), 0u);
  EXPECT_TRUE(all_written);
  EXPECT_GT(total, 0u);
  EXPECT_EQ(out.counters().epochs, 200u);
}
