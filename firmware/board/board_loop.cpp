#include "firmware/board/board_loop.hpp"

#include <array>

namespace sinu::board {

BoardLoop::BoardLoop(const BoardDevices& devices, const drivers::Icm20948Config& imu_config)
    : dev_(devices),
      imu_(devices.i2c, devices.clock, imu_config),
      poll_period_ns_(static_cast<hal::TimeNs>(0.5e9 / imu_config.odr_hz)) {}

void BoardLoop::poll_imu(BoardSink& sink, hal::TimeNs now_ns) {
  if (!polling_) {
    polling_ = true;
    ++counters_.polling_starts;
  }
  drivers::ImuSample sample;
  if (imu_.poll(now_ns, sample) == drivers::ImuRead::Sample) sink.on_imu(sample);
}

void BoardLoop::drain_serial(BoardSink& sink) {
  std::array<std::uint8_t, 256> buffer{};
  drivers::GpsFix fix;
  while (true) {
    const hal::SerialResult r = dev_.gps.read(buffer, 0);
    if (r.status == hal::SerialStatus::Error) ++counters_.serial_errors;
    if (r.status != hal::SerialStatus::Ok || r.bytes == 0) return;
    counters_.serial_bytes += r.bytes;
    for (std::size_t i = 0; i < r.bytes; ++i) {
      const bool got_fix = nmea_.push(static_cast<char>(buffer[i]), hal::ns_to_s(r.time_ns), fix);
      if (nmea_.sentence_ready()) sink.on_sentence(r.time_ns, nmea_.last_sentence());
      if (got_fix) sink.on_fix(fix);
    }
  }
}

void BoardLoop::run(BoardSink& sink, const std::atomic<bool>* stop, hal::TimeNs duration_ns) {
  const hal::TimeNs start = dev_.clock.now_ns();
  imu_.init();  // a failure is counted; read() retries with back-off
  drivers::ImuSample sample;
  while (!(stop && stop->load())) {
    hal::TimeNs edge_ns = 0;
    const hal::EdgeStatus st = dev_.drdy.wait_rising(polling_ ? poll_period_ns_ : kEdgeTimeoutNs, edge_ns);
    if (st == hal::EdgeStatus::Closed) break;
    if (st == hal::EdgeStatus::Edge) {
      ++counters_.edges;
      polling_ = false;  // edges are back
      if (imu_.read(edge_ns, sample) == drivers::ImuRead::Sample) sink.on_imu(sample);
    } else if (st == hal::EdgeStatus::OtherInput) {
      ++counters_.serial_wakeups;
    } else if (st == hal::EdgeStatus::Timeout) {
      ++counters_.edge_timeouts;
      poll_imu(sink, edge_ns);
    } else {  // an error is a timeout that came at once: poll, then wait as a timeout would have
      ++counters_.edge_errors;
      poll_imu(sink, edge_ns);
      dev_.clock.sleep_until_ns(edge_ns + poll_period_ns_);
    }
    drain_serial(sink);
    const hal::TimeNs now = dev_.clock.now_ns();
    sink.on_tick(now);
    if (duration_ns > 0 && now - start >= duration_ns) break;
  }
  drain_serial(sink);
  drivers::GpsFix fix;
  const double end_s = hal::ns_to_s(dev_.clock.now_ns());
  while (true) {
    const bool got_fix = nmea_.finish(end_s, fix);
    if (nmea_.sentence_ready()) sink.on_sentence(dev_.clock.now_ns(), nmea_.last_sentence());
    if (!got_fix) break;
    sink.on_fix(fix);
  }
}

}  // namespace sinu::board
