#include "firmware/board/fly_loop.hpp"

#include <cmath>
#include <cstdarg>
#include <numbers>

namespace sinu::board {

namespace {

constexpr hal::TimeNs kSyncPeriodNs = 1'000'000'000;

/// snprintf that appends at `used` and never overruns.
void append(char* buf, std::size_t size, std::size_t& used, const char* fmt, ...) {
  if (used + 1 >= size) return;
  va_list args;
  va_start(args, fmt);
  const int n = std::vsnprintf(buf + used, size - used, fmt, args);
  va_end(args);
  if (n > 0) used = std::min(size - 1, used + static_cast<std::size_t>(n));
}

}  // namespace

FlyLoop::FlyLoop(const BoardDevices& devices, const drivers::Icm20948Config& imu, const FlyOutputs& outputs,
                 hal::Clock& wall, const FlyLoopConfig& config)
    : loop_(devices, imu), outputs_(outputs), wall_(wall), config_(config) {}

bool FlyLoop::init(const NavUnitConfig& unit, std::string& error) {
  if (!unit_.init(unit, this, error)) return false;
  if (outputs_.log_path.empty()) return true;
  logging_ = log_.open(outputs_.log_path, unit_.navigator().filter().layout(), outputs_.log_period_s);
  if (!logging_) error = outputs_.log_path + ": cannot create the navigation log";
  return logging_;
}

bool FlyLoop::close_log(std::string& error) {
  if (!logging_) return true;
  logging_ = false;
  if (log_.close()) return true;
  error = outputs_.log_path + ": writing the navigation log failed (disk full?)";
  return false;
}

void FlyLoop::run(const std::atomic<bool>* stop, hal::TimeNs duration_ns) {
  last_report_wall_ns_ = wall_.now_ns();
  loop_.run(*this, stop, duration_ns);
  unit_.flush();
  if (logging_) log_.flush();
  if (config_.recording) config_.recording->sync();
}

void FlyLoop::on_imu(const drivers::ImuSample& sample) {
  last_sample_ns_ = sample.t_ns;
  have_sample_ = true;
  unit_.push_imu(sample);  // the unit's solutions reach the outputs from here (on_nav)
  const hal::TimeNs edge_wall = config_.edge_wall_ns ? *config_.edge_wall_ns : sample.t_ns;
  stats_.add(wall_.now_ns() - edge_wall);
}

void FlyLoop::on_fix(const drivers::GpsFix& fix) {
  if (!unit_.push_fix(fix)) return;
  ++fixes_;
  last_fix_ns_ = static_cast<hal::TimeNs>(std::llround(fix.arrival_s * 1e9));
  have_fix_ = true;
}

void FlyLoop::on_nav(const est::NavOutput& out) {
  unit_.solution(out, solution_);
  ++solutions_;
  flags_ |= out.flags;
  if (outputs_.mavlink) outputs_.mavlink->on_solution(solution_);
  if (outputs_.nmea) outputs_.nmea->offer(solution_);
  if (logging_) log_.on_nav(out, unit_.navigator().filter());
}

void FlyLoop::on_tick(hal::TimeNs now_ns) {
  if (now_ns - last_sync_ns_ >= kSyncPeriodNs) {  // at most a second lost on a crash or power cut
    last_sync_ns_ = now_ns;
    if (config_.recording) config_.recording->sync();
    if (logging_) log_.flush();
  }
  if (config_.health_period_s > 0.0 &&
      wall_.now_ns() - last_report_wall_ns_ >= static_cast<hal::TimeNs>(config_.health_period_s * 1e9)) {
    report(now_ns);
  }
}

void FlyLoop::report(hal::TimeNs now_ns) {
  last_report_wall_ns_ = wall_.now_ns();
  const drivers::Icm20948Counters& c = loop_.imu().counters();
  FlyHealth total;
  total.t_s = hal::ns_to_s(now_ns);
  total.imu_samples = c.samples;
  total.polled = c.polled;
  total.i2c_errors = c.i2c_errors;
  total.reinits = c.reinits;
  total.fixes = fixes_;
  const drivers::NmeaStreamCounters gps = loop_.gps_counters();
  total.corrupt_sentences = gps.sentences.corrupt();
  total.garbage_bytes = gps.framing.noise_bytes + gps.framing.interrupted + gps.framing.too_long;
  FlyHealth h = total;  // this period's
  h.imu_samples -= at_last_report_.imu_samples;
  h.polled -= at_last_report_.polled;
  h.i2c_errors -= at_last_report_.i2c_errors;
  h.reinits -= at_last_report_.reinits;
  h.fixes -= at_last_report_.fixes;
  h.corrupt_sentences -= at_last_report_.corrupt_sentences;
  h.garbage_bytes -= at_last_report_.garbage_bytes;
  h.since_imu_s = have_sample_ ? hal::ns_to_s(now_ns - last_sample_ns_) : -1.0;
  h.since_fix_s = have_fix_ ? hal::ns_to_s(now_ns - last_fix_ns_) : -1.0;
  at_last_report_ = total;
  char line[512];
  health_line(h, line, sizeof line);
  std::fprintf(config_.health, "%s\n", line);
  if (unit_.state_note_version() != state_note_printed_) {  // the state file: used, not, not written
    state_note_printed_ = unit_.state_note_version();
    std::fprintf(config_.health, "sinu fly: %s\n", unit_.state_note().c_str());
  }
  std::fflush(config_.health);
  flags_ = 0;
}

std::size_t FlyLoop::health_line(const FlyHealth& h, char* buf, std::size_t size) const {
  namespace f = est::nav_flag;
  constexpr double kRadToDeg = 180.0 / std::numbers::pi;
  std::size_t n = 0;
  buf[0] = '\0';
  append(buf, size, n, "sinu fly: t=%.1f s", h.t_s);
  const NavSolution& s = solution_;
  const est::SensorScaleVerdict& units = unit_.navigator().scale_verdict();
  if (units.accel_refused) {
    append(buf, size, n, " | NAV REFUSED: accelerometer reads %.3gx gravity and the turns (not m/s^2? driver scale)",
           units.specific_force_over_gravity);
  } else if (units.gyro_refused) {
    append(buf, size, n, " | NAV REFUSED: gyro scatters %.3g rad/s at rest (not rad/s? driver scale)",
           units.gyro_std_at_rest_rad_s);
  } else if (!unit_.navigator().aligned()) {
    append(buf, size, n, " | NAV aligning");
  } else {
    const std::uint32_t fl = s.flags | flags_;
    const char* state = (fl & f::kLost) ? "LOST" : (fl & f::kGnssTimeout) ? "COASTING (no GNSS)" : "ok";
    append(buf, size, n, " | NAV %s, sigma pos %.1f m vel %.2f m/s yaw %.1f deg", state,
           std::sqrt(s.P_nav(0, 0) + s.P_nav(1, 1)), std::sqrt(s.P_nav(3, 3) + s.P_nav(4, 4)),
           std::sqrt(s.P_nav(8, 8)) * kRadToDeg);
    if (fl & (f::kPositionReset | f::kVelocityReset | f::kYawReset)) append(buf, size, n, ", RESET to GNSS");
    if (fl & f::kClipping) append(buf, size, n, ", IMU CLIPPING");
    if (units.mag_refused()) {
      append(buf, size, n, ", MAG NOT USED: reads %.3gx the Earth's field (not uT?)", units.field_over_model);
    }
  }
  // IMU: unhealthy while samples are missing or transfers fail.
  const bool imu_bad = h.i2c_errors > 0 || h.since_imu_s < 0.0 || h.since_imu_s > 0.2;
  append(buf, size, n, " | IMU %s %llu samples", imu_bad ? "UNHEALTHY" : "ok", static_cast<unsigned long long>(h.imu_samples));
  if (h.i2c_errors > 0 || h.reinits > 0) {
    append(buf, size, n, ", %llu I2C errors, %llu re-inits", static_cast<unsigned long long>(h.i2c_errors),
           static_cast<unsigned long long>(h.reinits));
  }
  if (h.since_imu_s > 0.2) append(buf, size, n, ", none for %.1f s", h.since_imu_s);
  if (loop_.polling() || h.polled > 0) {
    append(buf, size, n, ", NO DATA-READY EDGES: polling (%llu polled)", static_cast<unsigned long long>(h.polled));
  }
  // GPS: fixes, silence, garbage.
  append(buf, size, n, " | GPS %llu fixes", static_cast<unsigned long long>(h.fixes));
  if (h.since_fix_s < 0.0) append(buf, size, n, ", none yet");
  else if (h.since_fix_s > 1.0) append(buf, size, n, ", SILENT for %.1f s", h.since_fix_s);
  if (h.corrupt_sentences > 0) append(buf, size, n, ", %llu CORRUPT sentences", static_cast<unsigned long long>(h.corrupt_sentences));
  if (h.garbage_bytes > 0) append(buf, size, n, ", GARBAGE (%llu bytes)", static_cast<unsigned long long>(h.garbage_bytes));
  if (s.satellites > 0) append(buf, size, n, ", %d sats", s.satellites);
  if (stats_.count() > 0) {
    append(buf, size, n, " | loop median %.2f ms worst %.2f ms", static_cast<double>(stats_.median_ns()) * 1e-6,
           static_cast<double>(stats_.worst_ns()) * 1e-6);
  }
  return n;
}

}  // namespace sinu::board
