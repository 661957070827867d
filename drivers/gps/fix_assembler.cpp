#include "drivers/gps/fix_assembler.hpp"

#include <type_traits>

namespace sinu::drivers {

static_assert(std::variant_size_v<NmeaMessage> <= 32, "a type bit each in a 32-bit mask");

namespace {

std::optional<UtcMs> time_of(const NmeaMessage& msg) {
  return std::visit(
      [](const auto& m) -> std::optional<UtcMs> {
        if constexpr (requires { m.utc_ms; }) return m.utc_ms;
        else return std::nullopt;
      },
      msg);
}

}  // namespace

void FixAssembler::merge(const NmeaMessage& msg) {
  std::visit(
      [this](const auto& m) {
        using T = std::decay_t<decltype(m)>;
        GpsFix& f = open_;
        if constexpr (std::is_same_v<T, GgaMessage>) {
          f.has_gga = true;
          f.quality = m.quality;
          if (m.lat_deg) f.lat_deg = m.lat_deg;
          if (m.lon_deg) f.lon_deg = m.lon_deg;
          f.alt_msl_m = m.alt_msl_m;
          f.geoid_sep_m = m.geoid_sep_m;
          f.sats = m.sats;
          if (m.hdop) f.hdop = m.hdop;
        } else if constexpr (std::is_same_v<T, RmcMessage>) {
          f.has_rmc = true;
          f.rmc_valid = m.valid;
          f.rmc_mode = m.mode;
          if (!f.has_gga) {
            f.lat_deg = m.lat_deg;
            f.lon_deg = m.lon_deg;
          }
          if (m.speed_m_s) f.speed_m_s = m.speed_m_s;
          if (m.course_deg) f.course_deg = m.course_deg;
          if (m.date) f.date = m.date;
        } else if constexpr (std::is_same_v<T, VtgMessage>) {
          f.vtg_mode = m.mode;
          if (!f.speed_m_s) f.speed_m_s = m.speed_m_s;
          if (!f.course_deg) f.course_deg = m.course_deg;
        } else if constexpr (std::is_same_v<T, GsaMessage>) {
          f.pdop = m.pdop;
          f.vdop = m.vdop;
          if (!f.hdop) f.hdop = m.hdop;
        } else if constexpr (std::is_same_v<T, GstMessage>) {
          f.has_gst = m.sigma_lat_m || m.sigma_lon_m;
          f.sigma_lat_m = m.sigma_lat_m;
          f.sigma_lon_m = m.sigma_lon_m;
          f.sigma_alt_m = m.sigma_alt_m;
        } else if constexpr (std::is_same_v<T, GllMessage>) {
          f.has_gll = true;
          f.gll_valid = m.valid;
          if (!f.has_gga && !f.has_rmc) {
            f.lat_deg = m.lat_deg;
            f.lon_deg = m.lon_deg;
          }
        } else if constexpr (std::is_same_v<T, ZdaMessage>) {
          if (m.date) f.date = m.date;
        }
      },
      msg);
}

// An epoch closed by a time change never held the ender (the ender emits at
// once): either nothing is learned yet, or the receiver skipped it this time.
void FixAssembler::learn_cycle_end() {
  if (cycle_end_ == SIZE_MAX) {
    cycle_end_ = last_type_;
    return;
  }
  short_epochs_ = last_type_ == short_end_ ? short_epochs_ + 1 : 1;
  short_end_ = last_type_;
  if (short_epochs_ >= kLowerAfter) {  // it has stopped sending the ender
    cycle_end_ = last_type_;
    short_epochs_ = 0;
  }
}

bool FixAssembler::emit(GpsFix& out) {
  if (!is_open_ || !has_time_) {
    is_open_ = false;
    return false;
  }
  out = open_;
  is_open_ = false;
  emitted_types_ = open_types_;
  if (last_type_ == cycle_end_) short_epochs_ = 0;
  have_emitted_ = true;
  emitted_utc_ms_ = open_.utc_ms;
  ++epochs_;
  return true;
}

bool FixAssembler::add(const NmeaMessage& msg, double arrival_s, GpsFix& out) {
  const std::optional<UtcMs> t = time_of(msg);
  const std::size_t type = msg.index();
  bool emitted = false;
  if (is_open_ && t && has_time_ && *t != open_.utc_ms) {
    learn_cycle_end();  // closed by a time change
    emitted = emit(out);
  }
  const std::uint32_t bit = 1u << type;
  if (!is_open_ && t && have_emitted_ && *t == emitted_utc_ms_) {
    // A sentence of the epoch just emitted. Counted, not made into an epoch.
    ++late_;
    dropping_ = true;
    if (!(emitted_types_ & bit)) {  // it came after the learned ender: the cycle ends later than thought
      cycle_end_ = type;
      emitted_types_ |= bit;
    }  // else the receiver repeats the epoch: the ender stands
    return emitted;
  }
  if (t) dropping_ = false;
  if (!is_open_ && !t && dropping_) {  // follows a late sentence: belongs to the emitted epoch
    ++late_;
    return emitted;
  }
  if (!is_open_) {
    open_ = GpsFix{};
    open_types_ = 0;
    open_.arrival_s = arrival_s;
    is_open_ = true;
    has_time_ = false;
  }
  if (t && !has_time_) {
    open_.utc_ms = *t;
    has_time_ = true;
  }
  merge(msg);
  open_types_ |= bit;
  last_type_ = type;
  if (!emitted && type == cycle_end_ && has_time_) emitted = emit(out);
  return emitted;
}

bool FixAssembler::flush(GpsFix& out) { return emit(out); }

}  // namespace sinu::drivers
