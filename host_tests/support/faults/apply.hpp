#pragma once
// One function per fault, applied to a dataset held in memory as lines.
#include <optional>

#include "host_tests/support/dataset_faults.hpp"
#include "host_tests/support/faults/text_lines.hpp"

namespace sinu::test::faults {

/// The files of a dataset folder; an absent optional file is nullopt.
struct DatasetText {
  TextLines imu;                        // line 0 is the header
  std::optional<TextLines> gps, truth;  // truth: line 0 is the header
};

/// t in [start_s, start_s + duration_s).
inline bool in_window(double t, double start_s, double duration_s) { return t >= start_s && t < start_s + duration_s; }

FaultEffect apply(const GnssPositionJump& f, DatasetText& d);
FaultEffect apply(const GnssGarbage& f, DatasetText& d);
FaultEffect apply(const GnssOutage& f, DatasetText& d);
FaultEffect apply(const ImuClip& f, DatasetText& d);
FaultEffect apply(const ImuGap& f, DatasetText& d);
FaultEffect apply(const ImuDropMagFirstRows& f, DatasetText& d);
FaultEffect apply(const DropLeadingSeconds& f, DatasetText& d);
FaultEffect apply(const KeepLeadingSeconds& f, DatasetText& d);
FaultEffect apply(const ImuTimeGlitch& f, DatasetText& d);
FaultEffect apply(const ImuNonFinite& f, DatasetText& d);
FaultEffect apply(const ImuBiasShift& f, DatasetText& d);

/// Removes the lines whose time (leading number) satisfies `drop`; lines
/// without a readable time stay. A file that did not end in a terminator
/// still does not when its last line goes. Returns how many went.
template <class Pred>
std::size_t remove_timed_lines(TextLines& lines, Pred drop) {
  const auto before = lines.size();
  const bool open_end = !lines.empty() && lines.back().eol.empty();
  std::erase_if(lines, [&](const TextLine& l) {
    const auto t = leading_number(l.text);
    return t && drop(*t);
  });
  if (open_end && !lines.empty()) lines.back().eol.clear();
  return before - lines.size();
}

}  // namespace sinu::test::faults
