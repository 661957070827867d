// Dataset -> raw recording (emulator + NMEA byte stream) -> dataset, and a
// recording with injected faults replayed through the same drivers.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "drivers/imu/emulated_icm20948.hpp"
#include "firmware/board/board_loop.hpp"
#include "firmware/host/convert/dataset_devices.hpp"
#include "firmware/host/convert/dataset_sink.hpp"
#include "hal/recording/recording_taps.hpp"
#include "hal/replay/replay_devices.hpp"
#include "host_tests/support/nmea_text.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/shared_data.hpp"
#include "host_tests/support/temp_dir.hpp"

using namespace sinu;

namespace {

/// 10 s at 40 Hz, a slow turn, mag every other row, temperature drifting;
/// 5 Hz GPS with one corrupt sentence.
void write_dataset(const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  std::ofstream imu(dir / "imu.csv");
  imu << "t,ax,ay,az,gx,gy,gz,mx,my,mz,temp\n";
  for (int k = 0; k < 400; ++k) {
    const double t = 1203.0 + k * 0.025;
    imu << std::fixed;
    imu.precision(6);
    imu << t << ",";
    imu.precision(9);
    imu << 0.3 * std::sin(0.5 * t) << "," << -0.1 << "," << -9.81 + 0.05 * std::cos(t) << "," << 0.01 << ","
        << -0.002 << "," << 0.2 * std::sin(0.1 * t) << ",";
    if (k % 2 == 0) imu << 21.5 << "," << -2.25 << "," << 43.0 + 0.1 * k;
    else imu << ",,";
    imu << "," << 30.0 + 0.001 * k << "\n";
  }
  std::ofstream gps(dir / "gps.nmea");
  for (int k = 0; k < 50; ++k) {
    char utc[32];
    std::snprintf(utc, sizeof utc, "1015%02d.%02d", 20 + k / 5, (k % 5) * 20);
    gps.precision(3);
    gps << std::fixed << 1203.01 + k * 0.2 << ","
        << test::nmea_with_checksum(std::string("GPGGA,") + utc + ",3024.51234,N,11421.12345,E,1,12,0.8,45.3,M,-2.1,M,,")
        << "\n";
    gps << 1203.02 + k * 0.2 << "," << (k == 7 ? "$GPRMC,garbage*00" : test::nmea_with_checksum(std::string("GPRMC,") + utc + ",A,3024.51234,N,11421.12345,E,10.0,90.0,220326,,,A")) << "\n";
  }
}

bool dataset_to_raw(const std::string& in, const std::string& out) {
  const auto r = test::run_sinu({"convert", in, out});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0;
}

}  // namespace

TEST(ReplayRoundTrip, DatasetToRawToDatasetIsBitExactAfterTheFirstQuantisation) {
  test::TempDir dir;
  const auto d1 = dir.path() / "d1";
  write_dataset(d1);
  const std::string r1 = dir.file("r1.raw"), r2 = dir.file("r2.raw");
  const std::string d2 = dir.file("d2"), d3 = dir.file("d3");
  ASSERT_TRUE(dataset_to_raw(d1.string(), r1));
  ASSERT_TRUE(dataset_to_raw(r1, d2));
  ASSERT_TRUE(dataset_to_raw(d2, r2));
  ASSERT_TRUE(dataset_to_raw(r2, d3));
  EXPECT_EQ(test::read_file(r1), test::read_file(r2)) << "raw -> dataset -> raw: the same bytes";
  EXPECT_EQ(test::read_file(d2 + "/imu.csv"), test::read_file(d3 + "/imu.csv"));
  EXPECT_EQ(test::read_file(d2 + "/gps.nmea"), test::read_file(d3 + "/gps.nmea"));
  // The first pass quantises to the sensor's LSB: d2 is d1 to half an LSB,
  // with the same times, the same empty magnetometer fields, and gps.nmea
  // identical (sentences keep their bytes and times, corrupt one included).
  EXPECT_EQ(test::read_file((d1 / "gps.nmea").string()).size() + 50 * 2 * 3, test::read_file(d2 + "/gps.nmea").size())
      << "times gain 3 decimals (microseconds)";
  std::ifstream a(d1 / "imu.csv"), b(d2 + "/imu.csv");
  std::string la, lb;
  std::getline(a, la);
  std::getline(b, lb);
  ASSERT_EQ(la, lb);
  int rows = 0;
  while (std::getline(a, la) && std::getline(b, lb)) {
    std::stringstream sa(la), sb(lb);
    std::string fa, fb;
    for (int col = 0; std::getline(sa, fa, ',') && std::getline(sb, fb, ','); ++col) {
      ASSERT_EQ(fa.empty(), fb.empty()) << "row " << rows << " col " << col;
      if (fa.empty()) continue;
      // Half an LSB: accel 9.80665/4096/2, gyro (pi/180)/32.8/2, mag 0.075 uT, temp 1/333.87/2; t exact.
      const double tol[] = {0.0, 1.2e-3, 1.2e-3, 1.2e-3, 2.7e-4, 2.7e-4, 2.7e-4, 0.075, 0.075, 0.075, 1.5e-3};
      EXPECT_NEAR(std::stod(fa), std::stod(fb), tol[col] + 1e-9) << "row " << rows << " col " << col;
    }
    ++rows;
  }
  EXPECT_EQ(rows, 400);
}

namespace {

/// Emulated board with a scripted fault schedule, recorded.
class ScriptedEdges final : public hal::GpioEdge {
 public:
  ScriptedEdges(drivers::EmulatedIcm20948& chip, hal::ManualClock& clock) : chip_(chip), clock_(clock) {}
  hal::EdgeStatus wait_rising(hal::TimeNs, hal::TimeNs& t) override {
    if (k_ == 400) return hal::EdgeStatus::Closed;
    if (k_ == 100) chip_.inject(drivers::EmulatorFault::Nack, 6);        // -> re-initialisation
    if (k_ == 200) chip_.inject(drivers::EmulatorFault::MagOverflow, 3);
    if (k_ == 300) chip_.inject(drivers::EmulatorFault::FifoOverflow);
    t = 10'000'000'000 + k_ * 25'000'000LL;
    clock_.advance_to_ns(t);
    drivers::EmulatedSample s;
    s.specific_force_b_m_s2 = {0.01 * k_, 0.0, -9.8};
    s.angular_rate_b_rad_s = {0.0, 0.001 * k_, 0.0};
    s.mag_b_uT = std::array<double, 3>{20.0, 0.0, 40.0};
    chip_.load(s);
    ++k_;
    return hal::EdgeStatus::Edge;
  }

 private:
  drivers::EmulatedIcm20948& chip_;
  hal::ManualClock& clock_;
  int k_ = 0;
};

class NoSerial final : public hal::SerialPort {
 public:
  bool set_baud(std::uint32_t) override { return true; }
  hal::SerialResult read(std::span<std::uint8_t>, hal::TimeNs) override { return {}; }
  hal::SerialResult write(std::span<const std::uint8_t> b) override { return {hal::SerialStatus::Ok, b.size(), 0}; }
};

class Collect final : public board::BoardSink {
 public:
  void on_imu(const drivers::ImuSample& s) override { samples.push_back(s); }
  void on_sentence(hal::TimeNs, std::string_view) override {}
  void on_fix(const drivers::GpsFix&) override {}
  std::vector<drivers::ImuSample> samples;
};

}  // namespace

TEST(ReplayRoundTrip, FaultyLiveRunAndItsReplayGiveTheSameSamplesBitForBit) {
  test::TempDir dir;
  const std::string raw = dir.file("live.raw");
  Collect live;
  drivers::Icm20948Counters live_counters;
  {
    hal::ManualClock clock(9'000'000'000);
    drivers::EmulatedIcm20948 chip;
    ScriptedEdges edges(chip, clock);
    NoSerial serial;
    hal::rec::RecordingWriter writer;
    ASSERT_TRUE(writer.open(raw));
    hal::rec::RecordingI2cBus i2c(chip, writer, clock);
    hal::rec::RecordingGpioEdge drdy(edges, writer);
    hal::rec::RecordingSerialPort gps(serial, writer, clock);
    // GPS set-up as `sinu record --gps-setup mtk` sends it: outputs a replay passes over.
    const std::string setup = "$PMTK220,200*2C\r\n";
    gps.write({reinterpret_cast<const std::uint8_t*>(setup.data()), setup.size()});
    gps.set_baud(115200);
    board::BoardLoop loop({drdy, i2c, gps, clock}, {});
    loop.run(live);
    live_counters = loop.imu().counters();
    ASSERT_TRUE(writer.close());
  }
  EXPECT_EQ(live_counters.reinits, 1u);
  EXPECT_EQ(live_counters.mag_overflow, 3u);
  EXPECT_EQ(live_counters.fifo_overflow, 1u);

  hal::ReplaySession session;
  std::string error;
  ASSERT_TRUE(session.load(raw, error)) << error;
  Collect replay;
  board::BoardLoop loop({session.drdy(), session.i2c(), session.serial(), session.clock()}, {});
  loop.run(replay);
  EXPECT_EQ(session.desyncs(), 0u);
  EXPECT_EQ(session.consumed(), session.records());
  const auto& c = loop.imu().counters();
  EXPECT_EQ(c.samples, live_counters.samples);
  EXPECT_EQ(c.reinits, live_counters.reinits);
  EXPECT_EQ(c.i2c_errors, live_counters.i2c_errors);
  EXPECT_EQ(c.mag_overflow, live_counters.mag_overflow);
  ASSERT_EQ(replay.samples.size(), live.samples.size());
  for (std::size_t i = 0; i < live.samples.size(); ++i) {
    const auto& a = live.samples[i];
    const auto& b = replay.samples[i];
    ASSERT_EQ(a.t_ns, b.t_ns);
    ASSERT_EQ(a.has_mag, b.has_mag);
    ASSERT_EQ(0, std::memcmp(&a.specific_force_b_m_s2, &b.specific_force_b_m_s2, sizeof a.specific_force_b_m_s2));
    ASSERT_EQ(0, std::memcmp(&a.angular_rate_b_rad_s, &b.angular_rate_b_rad_s, sizeof a.angular_rate_b_rad_s));
    ASSERT_EQ(0, std::memcmp(&a.mag_b_uT, &b.mag_b_uT, sizeof a.mag_b_uT));
    ASSERT_EQ(a.temp_degC, b.temp_degC);
  }
}

TEST(ReplayRoundTrip, RealDriveSurvivesTheRoundTrip) {
  SINU_REQUIRE_SHARED(drive, "data/real/drive_0708");
  test::TempDir dir;
  const std::string r1 = dir.file("r1.raw"), r2 = dir.file("r2.raw"), d2 = dir.file("d2");
  ASSERT_TRUE(dataset_to_raw(drive, r1));
  ASSERT_TRUE(dataset_to_raw(r1, d2));
  ASSERT_TRUE(dataset_to_raw(d2, r2));
  EXPECT_EQ(test::read_file(r1), test::read_file(r2));
  // gps.nmea keeps every sentence byte for byte.
  std::ifstream a(drive + "/gps.nmea"), b(d2 + "/gps.nmea");
  std::string la, lb;
  std::size_t lines = 0;
  while (std::getline(a, la) && std::getline(b, lb)) {
    ASSERT_EQ(la.substr(la.find(',')), lb.substr(lb.find(','))) << "line " << lines;
    ASSERT_NEAR(std::stod(la), std::stod(lb), 0.5e-6);
    ++lines;
  }
  EXPECT_EQ(lines, 6591u);
}
