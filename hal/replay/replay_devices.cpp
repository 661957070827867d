#include "hal/replay/replay_devices.hpp"

#include <algorithm>
#include <cstring>

namespace sinu::hal {

using rec::Kind;

bool ReplaySession::load(const std::string& path, std::string& error) {
  rec::RecordingReader reader;
  if (!reader.open(path)) {
    error = reader.message();
    return false;
  }
  return load(reader);
}

bool ReplaySession::load(rec::RecordingReader& reader) {
  records_.clear();
  bytes_.clear();
  cursor_ = 0;
  rec::Record r;
  rec::ReadStatus st;
  bool first = true;
  while ((st = reader.next(r)) == rec::ReadStatus::Record) {
    records_.push_back({r.kind, r.t_ns, bytes_.size(), r.payload.size()});
    bytes_.insert(bytes_.end(), r.payload.begin(), r.payload.end());
    if (first) clock_ = ManualClock(r.t_ns);
    first = false;
  }
  stop_message_ = st == rec::ReadStatus::End ? std::string() : reader.message();
  return true;
}

void ReplaySession::skip_outputs() {
  // What the board sent to the GPS (set-up commands, baud changes) has no
  // receiver in a replay: passed over wherever it sits.
  while (cursor_ < records_.size() &&
         (records_[cursor_].kind == Kind::SerialTx || records_[cursor_].kind == Kind::SerialBaud))
    consume(records_[cursor_]);
}

void ReplaySession::consume(const Entry& e) {
  clock_.advance_to_ns(e.t_ns);
  ++cursor_;
}

I2cStatus ReplaySession::I2c::transfer(Kind kind, std::uint8_t address, std::uint8_t reg, std::size_t n,
                                       std::uint8_t* out) {
  s_.skip_outputs();
  const Entry* e = s_.at();
  const std::uint8_t* p = e ? s_.payload(*e) : nullptr;
  if (!e || e->kind != kind || e->length != 3 + n || p[0] != address || p[1] != reg) {
    ++s_.desyncs_;
    return I2cStatus::Io;
  }
  if (out && n > 0) std::memcpy(out, p + 3, n);
  s_.consume(*e);
  return static_cast<I2cStatus>(p[2]);
}

I2cStatus ReplaySession::I2c::read_registers(std::uint8_t address, std::uint8_t reg, std::span<std::uint8_t> data) {
  return transfer(Kind::I2cRead, address, reg, data.size(), data.data());
}

I2cStatus ReplaySession::I2c::write_registers(std::uint8_t address, std::uint8_t reg,
                                              std::span<const std::uint8_t> data) {
  return transfer(Kind::I2cWrite, address, reg, data.size(), nullptr);
}

bool ReplaySession::Serial::set_baud(std::uint32_t) {
  const Entry* e = s_.at();
  if (e && e->kind == Kind::SerialBaud) s_.consume(*e);
  return true;
}

SerialResult ReplaySession::Serial::read(std::span<std::uint8_t> out, TimeNs) {
  if (chunk_offset_ == 0) s_.skip_outputs();
  const Entry* e = s_.at();
  if (!e) return {SerialStatus::Closed, 0, s_.clock_.now_ns()};
  if (e->kind != Kind::SerialRx || e->length < 1) return {SerialStatus::Ok, 0, s_.clock_.now_ns()};
  const std::size_t left = e->length - 1 - chunk_offset_;
  const std::size_t n = std::min(left, out.size());
  std::memcpy(out.data(), s_.payload(*e) + 1 + chunk_offset_, n);
  const TimeNs t = e->t_ns;
  chunk_offset_ += n;
  if (chunk_offset_ == e->length - 1) {
    chunk_offset_ = 0;
    s_.consume(*e);
  }
  return {SerialStatus::Ok, n, t};
}

SerialResult ReplaySession::Serial::write(std::span<const std::uint8_t> bytes) {
  const Entry* e = s_.at();
  if (e && e->kind == Kind::SerialTx) s_.consume(*e);
  return {SerialStatus::Ok, bytes.size(), s_.clock_.now_ns()};
}

EdgeStatus ReplaySession::Drdy::wait_rising(TimeNs timeout_ns, TimeNs& edge_time_ns) {
  s_.skip_outputs();
  while (const Entry* e = s_.at()) {
    if (e->kind == Kind::GpioEdge) {
      edge_time_ns = e->t_ns;
      s_.consume(*e);
      return EdgeStatus::Edge;
    }
    if (e->kind == Kind::EdgeTimeout) {  // the wait gave up here: the loop polled next
      edge_time_ns = e->t_ns;
      s_.consume(*e);
      return EdgeStatus::Timeout;
    }
    if (e->kind == Kind::SerialRx) {  // bytes arrived first: let the loop read them
      s_.clock_.advance_to_ns(std::min(e->t_ns, s_.clock_.now_ns() + timeout_ns));
      return EdgeStatus::OtherInput;
    }
    // An I2C transfer or a write nobody asked for at this point: the loop
    // took another path than during recording. Skip it so replay goes on.
    ++s_.desyncs_;
    s_.consume(*e);
  }
  return EdgeStatus::Closed;
}

}  // namespace sinu::hal
