#include "firmware/host/sim/gps_receiver.hpp"

#include <Eigen/Geometry>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <span>

#include "estimator/earth/wgs84.hpp"
#include "firmware/host/sim/nmea_format.hpp"

namespace sinu::sim {

namespace {
constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr double kKnot_m_s = 1852.0 / 3600.0;
constexpr int kSatellites = 11;
constexpr double kHdop = 0.9;
constexpr double kPseudorangeRms_m = 1.1;
// The date of UTC second `utc_s` counted from midnight of the clock's start date
// (a long flight may pass midnight). Uses the same centisecond rounding as the time field.
std::chrono::year_month_day utc_date(const UtcClock& c, double utc_s) {
  using namespace std::chrono;
  const long long day_offset = std::llround(utc_s * 100.0) / (86400LL * 100);
  const sys_days start = year_month_day{year{c.year}, month{static_cast<unsigned>(c.month)},
                                        day{static_cast<unsigned>(c.day)}};
  return year_month_day{start + days{day_offset}};
}

}  // namespace

Eigen::Vector3d GpsErrorModel::sigma_ned_m() const {
  return (white_sigma_ned_m.array().square() + gm_sigma_ned_m.array().square()).sqrt();
}

double geoid_separation_m(double lat, double lon) {
  return 25.0 * std::sin(2.0 * lat) * std::cos(lon) + 15.0 * std::cos(3.0 * lon) * std::cos(lat) - 5.0;
}

GpsReceiver::GpsReceiver(const GpsErrorModel& model, const Effects& fx, const UtcClock& clock, double fix_period_s,
                         std::uint64_t seed)
    : model_(model),
      clock_(clock),
      lever_arm_b_m_(sensor_effects(fx).lever_arm_b_m),
      latency_s_(sensor_effects(fx).gps_latency_s),
      velocity_latency_s_(sensor_effects(fx).gps_velocity_latency_s),
      rng_(seed, RngStream::Gps),
      corrupt_rng_(seed, RngStream::Corruption) {
  for (Eigen::Index i = 0; i < 3; ++i) gm_[i].init(model.gm_sigma_ned_m[i], model.gm_tau_s, fix_period_s, rng_);
}

void GpsReceiver::antenna(const TrueMotion& m, double& lat, double& lon, double& h, Eigen::Vector3d& v_n) const {
  namespace w = est::wgs84;
  const Eigen::Vector3d d_n = m.C_nb * lever_arm_b_m_;
  lat = m.lat_rad + d_n.x() / (w::meridian_radius_m(m.lat_rad) + m.h_m);
  lon = w::wrap_lon_rad(m.lon_rad + d_n.y() / ((w::transverse_radius_m(m.lat_rad) + m.h_m) * std::cos(m.lat_rad)));
  h = m.h_m - d_n.z();
  // Antenna velocity over the Earth: v + C_nb (omega_eb_b x l), omega_eb_b = omega_nb_b + C_bn omega_en_n.
  const Eigen::Vector3d omega_eb_b = m.omega_nb_b_rad_s + m.C_nb.transpose() * m.omega_en_n_rad_s;
  v_n = m.v_n_m_s + m.C_nb * omega_eb_b.cross(lever_arm_b_m_);
}

bool GpsReceiver::emit(char* buf, std::size_t len, double arrival_s, dataset::NmeaLogWriter& out) {
  ++sentences_;
  if (corrupt_rng_.uniform() < model_.corrupt_fraction) {
    len = corrupt_sentence(std::span<char>(buf, kSentenceBuffer), len, corrupt_rng_);
    ++corrupted_;
  }
  return out.write(arrival_s, std::string_view(buf, len));
}

void GpsReceiver::remember(const TrueMotion& m) {
  if (velocity_latency_s_ <= 0.0) return;
  double lat = 0.0, lon = 0.0, h = 0.0;
  Eigen::Vector3d v_n;
  antenna(m, lat, lon, h, v_n);
  past_velocity_n_.emplace_back(m.t_s, v_n);
  while (past_velocity_n_.front().first < m.t_s - 1.0) past_velocity_n_.pop_front();
}

Eigen::Vector3d GpsReceiver::velocity_before(const TrueMotion& m, const Eigen::Vector3d& v_now_n) const {
  // The antenna's velocity tau before the fix's instant, between the IMU
  // samples around it (linear: 25 ms at 40 Hz misses 1e-4 m/s through a
  // roll-in); before the first second, to first order along the acceleration.
  const double t = m.t_s - velocity_latency_s_;
  for (std::size_t i = 1; i < past_velocity_n_.size(); ++i) {
    const auto& [t1, v1] = past_velocity_n_[i];
    const auto& [t0, v0] = past_velocity_n_[i - 1];
    if (t0 <= t && t <= t1) return v0 + (v1 - v0) * ((t - t0) / std::max(t1 - t0, 1e-12));
  }
  return v_now_n - m.accel_n_m_s2 * velocity_latency_s_;
}

bool GpsReceiver::fix(const TrueMotion& m, double stamp_s, dataset::NmeaLogWriter& out) {
  namespace w = est::wgs84;
  double lat = 0.0, lon = 0.0, h = 0.0;
  Eigen::Vector3d v_n;
  antenna(m, lat, lon, h, v_n);
  Eigen::Vector3d e_n;
  for (Eigen::Index i = 0; i < 3; ++i) e_n[i] = gm_[i].step(rng_) + model_.white_sigma_ned_m[i] * rng_.normal();
  if (velocity_latency_s_ > 0.0) v_n = velocity_before(m, v_n);
  for (Eigen::Index i = 0; i < 3; ++i) v_n[i] += model_.velocity_sigma_ned_m_s[i] * rng_.normal();
  lat += e_n.x() / (w::meridian_radius_m(lat) + h);
  lon += e_n.y() / ((w::transverse_radius_m(lat) + h) * std::cos(lat));
  h -= e_n.z();
  const double lat_deg = lat * kRadToDeg, lon_deg = std::remainder(lon * kRadToDeg, 360.0);
  const double sep = geoid_separation_m(lat, lon);
  const double speed_kn = std::hypot(v_n.x(), v_n.y()) / kKnot_m_s;
  double course = std::atan2(v_n.y(), v_n.x()) * kRadToDeg;
  if (course < 0.0) course += 360.0;
  if (course >= 359.995) course = 0.0;  // prints as 360.00 otherwise
  const Eigen::Vector3d sigma = model_.sigma_ned_m();
  const double utc = stamp_s + clock_.utc_minus_board_s;

  char time_s[16], lat_s[24], lon_s[24];
  format_utc(time_s, utc);
  format_angle(lat_s, lat_deg, 2, 'N', 'S');
  format_angle(lon_s, lon_deg, 3, 'E', 'W');

  char buf[kSentenceBuffer];
  const std::span<char> b(buf, sizeof buf - 4);
  double arrival = stamp_s + model_.base_latency_s;
  int n = std::snprintf(buf, b.size(), "$GPGGA,%s,%s,%s,1,%02d,%.1f,%.3f,M,%.3f,M,,", time_s, lat_s, lon_s,
                        kSatellites, kHdop, h - sep, sep);
  bool ok = emit(buf, append_checksum(b, written_length(n, b.size())), arrival, out);
  arrival += model_.sentence_spacing_s;
  const std::chrono::year_month_day date = utc_date(clock_, utc);
  n = std::snprintf(buf, b.size(), "$GPRMC,%s,A,%s,%s,%.3f,%.2f,%02u%02u%02d,,,A", time_s, lat_s, lon_s, speed_kn,
                    course, static_cast<unsigned>(date.day()), static_cast<unsigned>(date.month()),
                    static_cast<int>(date.year()) % 100);
  ok = emit(buf, append_checksum(b, written_length(n, b.size())), arrival, out) && ok;
  arrival += model_.sentence_spacing_s;
  n = std::snprintf(buf, b.size(), "$GPGST,%s,%.1f,%.2f,%.2f,0.0,%.2f,%.2f,%.2f", time_s, kPseudorangeRms_m,
                    std::max(sigma.x(), sigma.y()), std::min(sigma.x(), sigma.y()), sigma.x(), sigma.y(), sigma.z());
  ok = emit(buf, append_checksum(b, written_length(n, b.size())), arrival, out) && ok;
  return ok;
}

}  // namespace sinu::sim
