// sinu fly's outputs, end to end: an emulated flight with MAVLink to a UDP
// socket on loopback and NMEA to a pty, every solution in the navigation log
// (--log-rate 0). What the flight controller would read is decoded by
// independent clients and must be the log's solution: MAVLink by the test's
// own decoder (mavlink_reference: ids, field layouts and CRC extras from the
// official definitions), NMEA by gpsd's gpsdecode.
#include <arpa/inet.h>
#include <fcntl.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <Eigen/Geometry>
#include <atomic>
#include <ctime>
#include <iomanip>
#include <chrono>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <thread>

#include "estimator/earth/wgs84.hpp"
#include "host_tests/board/fly_flight.hpp"
#include "host_tests/board/mavlink_reference.hpp"
#include "host_tests/support/run_process.hpp"

namespace sinu::test {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr const char* kGpsdecode = "/usr/bin/gpsdecode";

struct NavRow {
  double t, lat, lon, h, vn, ve, vd, roll, pitch, yaw;
};

/// nav.csv rows by time (the log's first ten columns).
std::map<double, NavRow> nav_rows(const std::string& path) {
  std::map<double, NavRow> out;
  for (const auto& r : read_csv_numbers(path).rows) out[r[0]] = {r[0], r[1], r[2], r[3], r[4], r[5], r[6], r[7], r[8], r[9]};
  return out;
}

const NavRow* row_at(const std::map<double, NavRow>& rows, double t) {
  const auto it = rows.lower_bound(t - 1e-6);  // the log prints t with 6 decimals
  return it != rows.end() && std::abs(it->first - t) < 1e-6 ? &it->second : nullptr;
}

/// C_nb of roll, pitch, yaw (ZYX), written here from the definition.
Eigen::Matrix3d c_nb(double roll, double pitch, double yaw) {
  return (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) * Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

/// ISO "2026-03-22T10:15:20.123Z" -> ms since 1970.
std::int64_t iso_ms(const std::string& s) {
  std::tm tm{};
  std::istringstream in(s);
  in >> std::get_time(&tm, "%Y-%m-%dT%H:%M:%S");
  const std::int64_t ms = std::stoll(s.substr(20, 3));
  return static_cast<std::int64_t>(timegm(&tm)) * 1000 + ms;
}

TEST(FlyOutputs, MavlinkOverUdpAndNmeaOverAPtyAreTheNavigationLog) {
  if (::access(kGpsdecode, X_OK) != 0) GTEST_SKIP() << kGpsdecode << " missing (gpsd-clients, tools/setup.sh)";
  TempDir tmp;
  const FlyFlight fl = make_fly_flight(tmp, "flight", 300, 21);
  // The flight controller's ends: a UDP socket and a pty.
  const int udp = ::socket(AF_INET, SOCK_DGRAM, 0);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  const int rcvbuf = 1 << 20;
  ::setsockopt(udp, SOL_SOCKET, SO_RCVBUF, &rcvbuf, sizeof rcvbuf);
  ASSERT_EQ(::bind(udp, reinterpret_cast<sockaddr*>(&addr), sizeof addr), 0);
  socklen_t len = sizeof addr;
  ::getsockname(udp, reinterpret_cast<sockaddr*>(&addr), &len);
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  ASSERT_GE(master, 0);
  ASSERT_EQ(::grantpt(master), 0);
  ASSERT_EQ(::unlockpt(master), 0);
  const std::string slave = ::ptsname(master);
  const std::string config = write_fly_config(
      tmp, "fly",
      "[outputs.mavlink]\nenabled = true\ntransport = \"udp\"\nudp_host = \"127.0.0.1\"\nudp_port = " +
          std::to_string(ntohs(addr.sin_port)) + "\n\n[outputs.nmea]\nenabled = true\ndevice = \"" + slave +
          "\"\nbaud = 115200\n");

  std::atomic<bool> done{false};
  ProcessResult result;
  std::thread flight([&] {
    // 20x real time: as fast as a test should wait, slow enough that the
    // socket's receive buffer never overflows (flat out, datagrams are dropped).
    result = run_sinu({"fly", "--config", config, "--emulate", fl.quantised, "--speed", "20", "--log-rate", "0",
                       "--health-period", "0"});
    done = true;
  });
  std::vector<mavref::Frame> frames;
  std::string nmea;
  std::vector<std::uint8_t> buf(65536);
  for (int idle = 0; idle < 5;) {  // read both until the flight ended and 0.5 s passed quietly
    pollfd p[2] = {{udp, POLLIN, 0}, {master, POLLIN, 0}};
    if (::poll(p, 2, 100) <= 0) {
      idle += done ? 1 : 0;
      continue;
    }
    if (p[0].revents & POLLIN) {
      const ssize_t n = ::recv(udp, buf.data(), buf.size(), 0);
      const mavref::ParseResult pr = mavref::parse({buf.data(), static_cast<std::size_t>(n)});
      EXPECT_EQ(pr.frames.size(), 1u) << "one frame per datagram";
      EXPECT_EQ(pr.bad_crc + pr.unknown_id + pr.noise_bytes, 0u);
      frames.insert(frames.end(), pr.frames.begin(), pr.frames.end());
    }
    if (p[1].revents & POLLIN) {
      const ssize_t n = ::read(master, buf.data(), buf.size());
      if (n > 0) nmea.append(reinterpret_cast<const char*>(buf.data()), static_cast<std::size_t>(n));
    }
    if (p[1].revents & POLLHUP) idle += done ? 1 : 0;  // the writer closed the pty
  }
  flight.join();
  ::close(udp);
  ::close(master);
  ASSERT_EQ(result.exit_code, 0) << result.err;
  const std::map<double, NavRow> rows = nav_rows(tmp.file("fly_nav.csv"));
  ASSERT_GT(rows.size(), 5000u);
  const NavRow& origin = rows.begin()->second;  // ODOMETRY's local frame starts at the first solution

  // MAVLink: each message is the logged solution of its time_usec.
  std::size_t heartbeats = 0, odometry = 0, gps_inputs = 0;
  std::map<std::int64_t, double> board_t_of_utc_ms;  // from GPS_INPUT, for the NMEA below
  for (const mavref::Frame& fr : frames) {
    if (fr.msgid == mavref::kPublishedHeartbeat.id) {
      ++heartbeats;
      continue;
    }
    const double t = fr.f("time_usec") * 1e-6;
    const NavRow* r = row_at(rows, t);
    ASSERT_NE(r, nullptr) << "message at t=" << t << " has no logged solution";
    const Eigen::Matrix3d C = c_nb(r->roll * kDeg, r->pitch * kDeg, r->yaw * kDeg);
    const Eigen::Vector3d v_n(r->vn, r->ve, r->vd);
    if (fr.msgid == mavref::kPublishedOdometry.id) {
      ++odometry;
      // float fields: 6e-8 relative; the log's 6 (angles) and 4 (v) decimals.
      const Eigen::Quaterniond q(fr.a("q")[0], fr.a("q")[1], fr.a("q")[2], fr.a("q")[3]);
      EXPECT_LT(Eigen::AngleAxisd(q.toRotationMatrix().transpose() * C).angle(), 1e-5) << "attitude at t=" << t;
      const Eigen::Vector3d v_b = C.transpose() * v_n;
      EXPECT_NEAR(fr.f("vx"), v_b.x(), 1e-3);
      EXPECT_NEAR(fr.f("vy"), v_b.y(), 1e-3);
      EXPECT_NEAR(fr.f("vz"), v_b.z(), 1e-3);
      const double lat_m = 0.5 * (origin.lat + r->lat) * kDeg, h_m = 0.5 * (origin.h + r->h);
      const double north = (r->lat - origin.lat) * kDeg * (est::wgs84::meridian_radius_m(lat_m) + h_m);
      const double east = (r->lon - origin.lon) * kDeg * (est::wgs84::transverse_radius_m(lat_m) + h_m) * std::cos(lat_m);
      // float at a few km: 0.5 mm; the log's 9 decimals of a degree: 0.1 mm.
      EXPECT_NEAR(fr.f("x"), north, 5e-3);
      EXPECT_NEAR(fr.f("y"), east, 5e-3);
      EXPECT_NEAR(fr.f("z"), origin.h - r->h, 5e-3);
    } else if (fr.msgid == mavref::kPublishedGpsInput.id) {
      ++gps_inputs;
      EXPECT_NEAR(fr.f("lat") * 1e-7, r->lat, 0.5e-7 + 1e-9);  // degE7 integers
      EXPECT_NEAR(fr.f("lon") * 1e-7, r->lon, 0.5e-7 + 1e-9);
      EXPECT_NEAR(fr.f("vn"), r->vn, 1e-3);
      EXPECT_NEAR(fr.f("ve"), r->ve, 1e-3);
      EXPECT_NEAR(fr.f("vd"), r->vd, 1e-3);
      EXPECT_EQ(fr.f("fix_type"), 3.0) << "a 3-D fix while navigating";
      const std::int64_t gps_ms = static_cast<std::int64_t>(fr.f("time_week")) * 604'800'000 +
                                  static_cast<std::int64_t>(fr.f("time_week_ms"));
      board_t_of_utc_ms[315'964'800'000LL + gps_ms - 18'000] = t;  // GPS = UTC + 18 s
    }
  }
  const double span = std::prev(rows.end())->first - origin.t;
  EXPECT_NEAR(static_cast<double>(heartbeats), span, 3.0) << "1 Hz";
  EXPECT_NEAR(static_cast<double>(odometry), 10.0 * span, 10.0) << "10 Hz";
  EXPECT_NEAR(static_cast<double>(gps_inputs), 5.0 * span, 5.0) << "5 Hz";

  // NMEA: gpsd's decoder; its time (UTC) is matched to the GPS_INPUT of the same solution.
  const std::string file = tmp.write("out.nmea", nmea);
  const ProcessResult gd = run_process({"/bin/sh", "-c", std::string("exec ") + kGpsdecode + " < '" + file + "'"});
  ASSERT_EQ(gd.exit_code, 0) << gd.err;
  std::size_t tpvs = 0, matched = 0;
  std::istringstream lines(gd.out);
  for (std::string l; std::getline(lines, l);) {
    const nlohmann::json j = nlohmann::json::parse(l);
    if (j.at("class") != "TPV" || !j.contains("lat")) continue;
    ++tpvs;
    const auto it = board_t_of_utc_ms.find(iso_ms(j.at("time").get<std::string>()));
    if (it == board_t_of_utc_ms.end()) continue;
    const NavRow* r = row_at(rows, it->second);
    ASSERT_NE(r, nullptr);
    ++matched;
    // Our 6 decimals of a minute (8.3e-9 deg) + gpsdecode's 9 decimals + the log's 9.
    EXPECT_NEAR(j.at("lat").get<double>(), r->lat, 8.4e-9 + 1e-9);
    EXPECT_NEAR(j.at("lon").get<double>(), r->lon, 8.4e-9 + 1e-9);
    EXPECT_NEAR(j.at("altHAE").get<double>(), r->h, 1.1e-3 + 0.5e-4);  // two 1-mm fields, the log's 4 decimals
    EXPECT_NEAR(j.at("speed").get<double>(), std::hypot(r->vn, r->ve), 0.26e-3 + 0.5e-3 + 1e-4);
  }
  EXPECT_NEAR(static_cast<double>(tpvs), 5.0 * span, 6.0) << "5 Hz epochs, gpsd reports all but the first";
  EXPECT_GE(matched, tpvs - 2) << "each epoch is the solution a GPS_INPUT also carried";
}

}  // namespace
}  // namespace sinu::test
