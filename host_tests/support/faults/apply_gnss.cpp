// The gps.nmea faults: position jump, garbage, outage.
#include "host_tests/support/faults/apply.hpp"
#include "host_tests/support/faults/nmea_garbage.hpp"
#include "host_tests/support/faults/nmea_position_shift.hpp"

namespace sinu::test::faults {

namespace {

/// Calls edit(sentence) for every line arriving in the window; edit returns
/// the new sentence or nullopt to leave the line alone. Returns lines changed.
template <class Edit>
std::size_t edit_sentences(TextLines& lines, double start_s, double duration_s, Edit edit) {
  std::size_t changed = 0;
  for (auto& line : lines) {
    const auto t = leading_number(line.text);
    if (!t || !in_window(*t, start_s, duration_s)) continue;
    const std::size_t comma = line.text.find(',');  // a readable time implies one
    const std::string_view sentence = std::string_view(line.text).substr(comma + 1);
    if (auto replaced = edit(sentence)) {
      line.text = line.text.substr(0, comma + 1) + *replaced;
      ++changed;
    }
  }
  return changed;
}

}  // namespace

FaultEffect apply(const GnssPositionJump& f, DatasetText& d) {
  if (!d.gps) return {};
  return {edit_sentences(*d.gps, f.start_s, f.duration_s,
                         [&](std::string_view s) { return shift_position(s, f.offset_ned_m); }),
          0};
}

FaultEffect apply(const GnssGarbage& f, DatasetText& d) {
  if (!d.gps) return {};
  GarbageGenerator garbage(f.seed);
  return {edit_sentences(*d.gps, f.start_s, f.duration_s,
                         [&](std::string_view s) { return std::optional<std::string>(garbage.next(s)); }),
          0};
}

FaultEffect apply(const GnssOutage& f, DatasetText& d) {
  if (!d.gps) return {};
  return {0, remove_timed_lines(*d.gps, [&](double t) { return in_window(t, f.start_s, f.duration_s); })};
}

}  // namespace sinu::test::faults
