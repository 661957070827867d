// The fault injector on a simulated flight, each fault checked with the
// project's own readers (dataset::CsvReader, dataset::NmeaLogReader / GpsLogReader,
// drivers::NmeaParser) and byte for byte outside its window.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "firmware/host/dataset/nmea_log.hpp"
#include "host_tests/sim/gps_log.hpp"
#include "host_tests/sim/sim_test_support.hpp"
#include "host_tests/support/dataset_faults.hpp"

using namespace sinu;
using namespace sinu::test;
namespace ic = dataset::imu_col;

namespace {

/// Lines of a file, each with its terminator (so comparisons see CR LF too).
std::vector<std::string> lines_of(const std::string& path) {
  const std::string bytes = read_file(path);
  std::vector<std::string> out;
  std::size_t begin = 0;
  while (begin < bytes.size()) {
    const std::size_t lf = bytes.find('\n', begin);
    const std::size_t end = lf == std::string::npos ? bytes.size() : lf + 1;
    out.push_back(bytes.substr(begin, end - begin));
    begin = end;
  }
  return out;
}

/// The number before a line's first comma (NaN for a header).
double time_of(const std::string& line) {
  const std::string prefix = line.substr(0, line.find(','));
  char* end = nullptr;
  const double t = std::strtod(prefix.c_str(), &end);
  return end == prefix.c_str() + prefix.size() && !prefix.empty() ? t : std::nan("");
}

std::vector<std::string> fields_of(std::string line) {
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  std::vector<std::string> f;
  std::size_t begin = 0;
  for (std::size_t comma; (comma = line.find(',', begin)) != std::string::npos; begin = comma + 1)
    f.push_back(line.substr(begin, comma - begin));
  f.push_back(line.substr(begin));
  return f;
}

bool in_window(double t, double start, double duration) { return t >= start && t < start + duration; }

/// The lines of `lines` whose time is not in the window (headers stay).
std::vector<std::string> without_window(const std::vector<std::string>& lines, double start, double duration) {
  std::vector<std::string> kept;
  for (const auto& l : lines)
    if (!in_window(time_of(l), start, duration)) kept.push_back(l);
  return kept;
}

/// North/east metres between two positions, WGS-84 radii at lat0.
void delta_ne_m(double lat0, double lon0, double lat1, double lon1, double& north, double& east) {
  north = (lat1 - lat0) * kDeg * ref::r_meridian(lat0 * kDeg);
  east = (lon1 - lon0) * kDeg * ref::r_transverse(lat0 * kDeg) * std::cos(lat0 * kDeg);
}

/// Digits after the '.' of a sentence's field `index` (0 = address).
int decimals_of_field(const std::string& sentence, std::size_t index) {
  const std::string f = fields_of(sentence.substr(1)).at(index);
  const std::size_t dot = f.find('.');
  return dot == std::string::npos ? 0 : static_cast<int>(f.size() - dot - 1);
}

/// Metres of latitude one unit of the last minute decimal rounds to, halved:
/// the most a re-rounded ddmm.mmmm field can be off (about 1852 m per arc minute).
double half_step_m(int minute_decimals, double lat_deg) {
  return 0.5 * std::pow(10.0, -minute_decimals) / 60.0 * kDeg * ref::r_meridian(lat_deg * kDeg);
}

/// Time and position of a GGA or RMC message.
struct Position {
  std::optional<drivers::UtcMs> utc_ms;
  std::optional<double> lat_deg, lon_deg;
};
Position position_of(const drivers::NmeaMessage& m) {
  if (const auto* g = std::get_if<drivers::GgaMessage>(&m)) return {g->utc_ms, g->lat_deg, g->lon_deg};
  const auto& r = std::get<drivers::RmcMessage>(m);
  return {r.utc_ms, r.lat_deg, r.lon_deg};
}

std::vector<drivers::GpsFix> read_fixes(const std::string& path) {
  dataset::GpsLogReader r;
  EXPECT_TRUE(r.open(path));
  std::vector<drivers::GpsFix> fixes;
  drivers::GpsFix fix;
  dataset::ReadStatus s;
  while ((s = r.next(fix)) == dataset::ReadStatus::Row) fixes.push_back(fix);
  EXPECT_EQ(s, dataset::ReadStatus::End) << r.error().to_string();
  return fixes;
}

}  // namespace

// One simulated 300 s flight (the simulator's minimum) shared by the suite,
// with 1 % of the sentences corrupted by the simulator itself: corrupt input
// must stay corrupt (never be "repaired" by a recomputed checksum).
class DatasetFaults : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    flight_ = std::make_unique<SimRun>();
    sim::SimOptions o;
    o.seed = 21;
    o.duration_s = 300.0;
    o.gps.corrupt_fraction = 0.01;
    run(*flight_, o);
  }
  static void TearDownTestSuite() { flight_.reset(); }
  void SetUp() override { ASSERT_TRUE(std::filesystem::exists(src("gps.nmea"))) << "the simulation failed"; }

  static std::string src(const char* f) { return flight_->path(f); }
  std::string dst(const char* f) const { return out_.file(f); }
  std::vector<FaultEffect> inject(const std::vector<Fault>& faults) const {
    return inject_faults(flight_->dir.path(), out_.path(), faults);
  }
  static DatasetTimes times() { return dataset_times(flight_->dir.path()); }
  void expect_copied(const char* f) const { EXPECT_EQ(read_file(dst(f)), read_file(src(f))) << f; }
  /// After a cut of every file at `cut`: each file holds its header and
  /// exactly the original lines on the kept side (from the cut on, or before
  /// it); the lines removed over all files.
  std::size_t expect_cut_at(double cut, bool keep_before) const {
    std::size_t removed = 0;
    for (const char* f : {"imu.csv", "gps.nmea", "truth.csv"}) {
      const auto before = lines_of(src(f)), after = lines_of(dst(f));
      const bool csv = std::string(f) != "gps.nmea";
      std::vector<std::string> expected;
      if (csv) expected.push_back(before[0]);
      for (const auto& l : before)
        if (keep_before ? time_of(l) < cut : time_of(l) >= cut) expected.push_back(l);
      EXPECT_EQ(after, expected) << f;
      EXPECT_GT(after.size(), csv ? 1u : 0u) << f;
      removed += before.size() - after.size();
    }
    return removed;
  }

  static inline std::unique_ptr<SimRun> flight_;
  TempDir out_;
};

TEST_F(DatasetFaults, TimesAreTheFirstAndLastOfEachFile) {
  const DatasetTimes t = times();
  const auto imu = flight_->imu();
  const auto gps = read_gps_log(src("gps.nmea"));
  ASSERT_FALSE(imu.empty());
  ASSERT_FALSE(gps.empty());
  EXPECT_EQ(t.imu.first_s, imu.front().t());
  EXPECT_EQ(t.imu.last_s, imu.back().t());
  EXPECT_EQ(t.gps.first_s, gps.front().arrival_s);
  EXPECT_EQ(t.gps.last_s, gps.back().arrival_s);
}

TEST_F(DatasetFaults, PositionJumpMovesEverySentenceInTheWindowByTheOffset) {
  const std::array<double, 3> offset{12.5, -7.25, 3.0};
  const double start = times().gps.first_s + 100.0, duration = 30.0;
  const auto effects = inject({GnssPositionJump{start, duration, offset}});
  const auto before = read_gps_log(src("gps.nmea")), after = read_gps_log(dst("gps.nmea"));
  ASSERT_EQ(before.size(), after.size());
  std::size_t shifted = 0, corrupt_in_window = 0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    const GpsLine &b = before[i], &a = after[i];
    EXPECT_EQ(a.arrival_s, b.arrival_s);
    const bool position = b.message && (std::holds_alternative<drivers::GgaMessage>(*b.message) ||
                                        std::holds_alternative<drivers::RmcMessage>(*b.message));
    if (!in_window(b.arrival_s, start, duration) || !position) {
      EXPECT_EQ(a.sentence, b.sentence) << "line " << i + 1 << " changed";
      corrupt_in_window += in_window(b.arrival_s, start, duration) && !b.checksum_ok;
      continue;
    }
    ASSERT_TRUE(a.checksum_ok) << a.sentence;
    ASSERT_TRUE(a.message && a.message->index() == b.message->index()) << a.sentence;
    ++shifted;
    // The new field is the exact shifted value rounded to the field's own
    // decimals (6 minute decimals here: 1.9 mm steps), so the decoded shift
    // is the offset within half a step, 0.93 mm: well inside 0.01 m. The
    // same bound holds for the altitude's 3 decimals (0.5 mm).
    const std::size_t lat_field = std::holds_alternative<drivers::GgaMessage>(*b.message) ? 2 : 3;
    const int lat_decimals = decimals_of_field(b.sentence, lat_field);
    EXPECT_EQ(decimals_of_field(a.sentence, lat_field), lat_decimals) << a.sentence;
    EXPECT_EQ(decimals_of_field(a.sentence, lat_field + 2), decimals_of_field(b.sentence, lat_field + 2));
    const double tol = half_step_m(lat_decimals, *position_of(*b.message).lat_deg) + 1e-6;
    ASSERT_LE(tol, 0.01);
    const auto pb = position_of(*b.message), pa = position_of(*a.message);
    double north = 0, east = 0;
    delta_ne_m(*pb.lat_deg, *pb.lon_deg, *pa.lat_deg, *pa.lon_deg, north, east);
    EXPECT_NEAR(north, offset[0], tol) << a.sentence;
    EXPECT_NEAR(east, offset[1], tol) << a.sentence;
    EXPECT_EQ(pa.utc_ms, pb.utc_ms);
    if (const auto* gb = std::get_if<drivers::GgaMessage>(&*b.message)) {
      const auto& ga = std::get<drivers::GgaMessage>(*a.message);
      EXPECT_NEAR(*ga.alt_msl_m - *gb->alt_msl_m, -offset[2], 0.0005 + 1e-9);
      EXPECT_EQ(ga.geoid_sep_m, gb->geoid_sep_m);
    } else {
      const auto &rb = std::get<drivers::RmcMessage>(*b.message), &ra = std::get<drivers::RmcMessage>(*a.message);
      EXPECT_EQ(ra.speed_m_s, rb.speed_m_s);
      EXPECT_EQ(ra.course_deg, rb.course_deg);
    }
  }
  EXPECT_GT(shifted, 250u) << "30 s of 5 Hz GGA + RMC";
  const auto raw_before = lines_of(src("gps.nmea")), raw_after = lines_of(dst("gps.nmea"));
  EXPECT_EQ(without_window(raw_after, start, duration), without_window(raw_before, start, duration));
  EXPECT_EQ(effects.at(0).changed, shifted);
  EXPECT_EQ(effects.at(0).removed, 0u);
  std::printf("jump: %zu sentences shifted, %zu corrupt ones in the window left alone\n", shifted, corrupt_in_window);

  // Through the fix assembler: epochs whose sentences all arrived in the
  // window (GGA first; RMC, GST within 16 ms) moved, the others unchanged.
  const auto fb = read_fixes(src("gps.nmea")), fa = read_fixes(dst("gps.nmea"));
  ASSERT_EQ(fb.size(), fa.size());
  std::size_t moved = 0;
  for (std::size_t i = 0; i < fb.size(); ++i) {
    const auto &b = fb[i], &a = fa[i];
    ASSERT_EQ(a.utc_ms, b.utc_ms);
    EXPECT_EQ(a.speed_m_s, b.speed_m_s);
    EXPECT_EQ(a.course_deg, b.course_deg);
    if (b.arrival_s < start - 0.1 || b.arrival_s >= start + duration) {
      EXPECT_EQ(a.lat_deg, b.lat_deg);
      EXPECT_EQ(a.lon_deg, b.lon_deg);
      EXPECT_EQ(a.ellipsoid_height_m(), b.ellipsoid_height_m());
    } else if (b.arrival_s >= start && b.arrival_s < start + duration - 0.1 && b.has_gga && b.has_rmc &&
               b.has_position()) {
      double north = 0, east = 0;
      delta_ne_m(*b.lat_deg, *b.lon_deg, *a.lat_deg, *a.lon_deg, north, east);
      EXPECT_NEAR(north, offset[0], 0.01);
      EXPECT_NEAR(east, offset[1], 0.01);
      EXPECT_NEAR(*a.ellipsoid_height_m() - *b.ellipsoid_height_m(), -offset[2], 0.01);
      ++moved;
    }
  }
  EXPECT_GT(moved, 130u);
  EXPECT_EQ(read_file(dst("imu.csv")), read_file(src("imu.csv")));
  expect_copied("truth.csv");
  expect_copied("meta.json");
}

TEST_F(DatasetFaults, GarbageIsCountedCorruptByTheReaderAndDeterministicPerSeed) {
  const double start = times().gps.first_s + 50.0, duration = 20.0;
  inject({GnssGarbage{start, duration, 7}});
  const auto before = lines_of(src("gps.nmea")), after = lines_of(dst("gps.nmea"));
  ASSERT_EQ(before.size(), after.size()) << "no line split or joined";

  // Outside the window byte for byte; inside, the arrival prefix kept and the
  // line still ends at its own LF (the split above would see any other).
  std::size_t in = 0, control = 0, high = 0, truncated = 0, wrong_checksum = 0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (!in_window(time_of(before[i]), start, duration)) {
      EXPECT_EQ(after[i], before[i]);
      continue;
    }
    ++in;
    const std::size_t comma = before[i].find(',');
    ASSERT_EQ(after[i].substr(0, comma + 1), before[i].substr(0, comma + 1));
    ASSERT_EQ(after[i].back(), '\n');
    const std::string s = after[i].substr(comma + 1, after[i].size() - comma - 2);
    EXPECT_EQ(s.find('\r'), std::string::npos);
    EXPECT_LE(s.size(), 250u);
    const bool ctl = std::any_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; });
    const bool hi = std::any_of(s.begin(), s.end(), [](char c) { return static_cast<unsigned char>(c) > 0x7e; });
    control += ctl;
    high += hi;
    if (!ctl && !hi && !s.empty() && s[0] == '$') {
      truncated += s.find('*') == std::string::npos;
      wrong_checksum += s.size() > 3 && s[s.size() - 3] == '*';
    }
  }
  EXPECT_GT(in, 250u) << "20 s of 15 sentences a second";
  EXPECT_GT(control, 20u);
  EXPECT_GT(high, 20u);
  EXPECT_GT(truncated, 20u);
  EXPECT_GT(wrong_checksum, 20u);

  // The project's reader: every line still read (the arrival prefix parses),
  // every window line rejected by the parser, the others as before.
  auto parse_all = [](const std::string& path, std::vector<drivers::ParseResult>& results) {
    dataset::NmeaLogReader log;
    EXPECT_TRUE(log.open(path));
    drivers::NmeaParser parser;
    dataset::NmeaLogLine line;
    drivers::NmeaMessage msg;
    dataset::ReadStatus s;
    while ((s = log.next(line)) == dataset::ReadStatus::Row) results.push_back(parser.parse(line.sentence, msg));
    EXPECT_EQ(s, dataset::ReadStatus::End) << log.error().to_string();
    EXPECT_EQ(log.skipped_lines(), 0u) << log.first_skipped().to_string();
    return parser.counters();
  };
  std::vector<drivers::ParseResult> rb, ra;
  const auto cb = parse_all(src("gps.nmea"), rb), ca = parse_all(dst("gps.nmea"), ra);
  ASSERT_EQ(ra.size(), before.size());
  std::uint64_t corrupt_outside = 0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (in_window(time_of(before[i]), start, duration)) {
      EXPECT_EQ(ra[i], drivers::ParseResult::Corrupt) << "line " << i + 1 << ": " << after[i];
    } else {
      EXPECT_EQ(ra[i], rb[i]);
      corrupt_outside += rb[i] == drivers::ParseResult::Corrupt;
    }
  }
  EXPECT_EQ(ca.corrupt(), corrupt_outside + in);
  EXPECT_EQ(ca.total(), cb.total());
  std::printf(
      "garbage: %zu lines, parser counts bad_checksum %llu missing_checksum %llu too_long %llu "
      "bad_framing %llu malformed %llu\n",
      in, static_cast<unsigned long long>(ca.bad_checksum - cb.bad_checksum),
      static_cast<unsigned long long>(ca.missing_checksum - cb.missing_checksum),
      static_cast<unsigned long long>(ca.too_long - cb.too_long),
      static_cast<unsigned long long>(ca.bad_framing - cb.bad_framing),
      static_cast<unsigned long long>(ca.malformed_field - cb.malformed_field));

  // Same seed, same bytes; another seed, other bytes.
  TempDir again, other;
  inject_faults(flight_->dir.path(), again.path(), {GnssGarbage{start, duration, 7}});
  inject_faults(flight_->dir.path(), other.path(), {GnssGarbage{start, duration, 8}});
  EXPECT_EQ(read_file(again.file("gps.nmea")), read_file(dst("gps.nmea")));
  EXPECT_NE(read_file(other.file("gps.nmea")), read_file(dst("gps.nmea")));
  expect_copied("imu.csv");
  expect_copied("truth.csv");
  expect_copied("meta.json");
}

TEST_F(DatasetFaults, GnssOutageRemovesExactlyTheWindow) {
  const double start = times().gps.first_s + 150.0, duration = 25.0;
  const auto effects = inject({GnssOutage{start, duration}});
  const auto before = lines_of(src("gps.nmea"));
  const auto kept = without_window(before, start, duration);
  EXPECT_EQ(lines_of(dst("gps.nmea")), kept);
  EXPECT_EQ(effects.at(0).removed, before.size() - kept.size());
  EXPECT_GT(effects.at(0).removed, 300u);
  for (const auto& fix : read_fixes(dst("gps.nmea"))) EXPECT_FALSE(in_window(fix.arrival_s, start, duration));
  expect_copied("imu.csv");
  expect_copied("truth.csv");
}

TEST_F(DatasetFaults, ImuGapRemovesExactlyTheWindow) {
  const double start = times().imu.first_s + 200.0, duration = 3.5;
  const auto effects = inject({ImuGap{start, duration}});
  const auto before = lines_of(src("imu.csv"));
  const auto kept = without_window(before, start, duration);
  const auto after = lines_of(dst("imu.csv"));
  EXPECT_EQ(after, kept);
  EXPECT_EQ(after.at(0), "t,ax,ay,az,gx,gy,gz,mx,my,mz,temp\n");
  EXPECT_EQ(effects.at(0).removed, 140u) << "3.5 s at 40 Hz";
  const auto rows = load_rows(dst("imu.csv"), dataset::kImuSchema);  // fails the test on any read error
  EXPECT_EQ(rows.size(), kept.size() - 1);
  for (const auto& r : rows) EXPECT_FALSE(in_window(r.t(), start, duration));
  expect_copied("gps.nmea");
  expect_copied("truth.csv");
}

TEST_F(DatasetFaults, PeggedClipReadsFullScaleOnTheChosenAxesOnly) {
  ImuClip clip;
  clip.start_s = times().imu.first_s + 60.0;
  clip.duration_s = 5.0;
  clip.accel_full_scale_m_s2 = 2.0 * 9.80665;
  clip.gyro_full_scale_rad_s = 250.0 * kDeg;
  clip.mode = ClipMode::Pegged;
  clip.accel_direction = {1, 0, -1};
  clip.gyro_direction = {0, -1, 0};
  const auto effects = inject({clip});
  EXPECT_EQ(effects.at(0).changed, 200u) << "5 s at 40 Hz";

  const auto before = lines_of(src("imu.csv")), after = lines_of(dst("imu.csv"));
  ASSERT_EQ(before.size(), after.size());
  const auto rows = load_rows(dst("imu.csv"), dataset::kImuSchema);
  ASSERT_EQ(rows.size() + 1, after.size());
  std::size_t pegged = 0;
  for (std::size_t i = 1; i < before.size(); ++i) {
    if (!in_window(time_of(before[i]), clip.start_s, clip.duration_s)) {
      EXPECT_EQ(after[i], before[i]);
      continue;
    }
    const auto& r = rows[i - 1];
    EXPECT_EQ(r.value[ic::ax], clip.accel_full_scale_m_s2);
    EXPECT_EQ(r.value[ic::az], -clip.accel_full_scale_m_s2);
    EXPECT_EQ(r.value[ic::gy], -clip.gyro_full_scale_rad_s);
    const auto fb = fields_of(before[i]), fa = fields_of(after[i]);
    ASSERT_EQ(fa.size(), fb.size());
    for (std::size_t c : {ic::t, ic::ay, ic::gx, ic::gz, ic::mx, ic::my, ic::mz, ic::temp})
      EXPECT_EQ(fa[c], fb[c]) << "column " << c << " of line " << i + 1;
    EXPECT_EQ(after[i].back(), '\n');
    ++pegged;
  }
  EXPECT_EQ(pegged, 200u);
  expect_copied("gps.nmea");
  expect_copied("truth.csv");
}

TEST_F(DatasetFaults, VibrationClipStaysWithinFullScaleAndShiftsTheMean) {
  ImuClip clip;
  clip.start_s = times().imu.first_s + 120.0;
  clip.duration_s = 10.0;
  clip.accel_full_scale_m_s2 = 2.0 * 9.80665;
  clip.mode = ClipMode::Vibration;  // 3 x full scale at 7.3 Hz, gyro untouched
  inject({clip});
  const double fs = clip.accel_full_scale_m_s2;

  const auto before = lines_of(src("imu.csv")), after = lines_of(dst("imu.csv"));
  const auto rb = flight_->imu(), ra = load_rows(dst("imu.csv"), dataset::kImuSchema);
  ASSERT_EQ(ra.size(), rb.size());
  std::size_t n = 0, at_full_scale = 0;
  double mean_before = 0.0, mean_after = 0.0;
  for (std::size_t i = 0; i < rb.size(); ++i) {
    if (!in_window(rb[i].t(), clip.start_s, clip.duration_s)) {
      EXPECT_EQ(after[i + 1], before[i + 1]);
      continue;
    }
    ++n;
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const double v = ra[i].value[ic::ax + axis], true_v = rb[i].value[ic::ax + axis];
      EXPECT_LE(std::abs(v), fs);
      const double phase =
          2.0 * std::numbers::pi * clip.vibration_hz * (rb[i].t() - clip.start_s) + clip.vibration_phase_rad[axis];
      EXPECT_NEAR(v, std::clamp(true_v + 3.0 * fs * std::sin(phase), -fs, fs), 1e-12 * fs);
      at_full_scale += std::abs(v) == fs;
    }
    for (std::size_t c = ic::gx; c < ic::count; ++c) EXPECT_EQ(fields_of(after[i + 1])[c], fields_of(before[i + 1])[c]);
    mean_before += rb[i].value[ic::az] / 400.0;
    mean_after += ra[i].value[ic::az] / 400.0;
  }
  ASSERT_EQ(n, 400u);
  // |sin| > 1/3 for 78 % of the phase: most samples sit at a rail.
  EXPECT_GT(at_full_scale, 3 * n / 2);
  // Clipping a vibration around az = -g (half the full scale) is asymmetric:
  // the mean moves from -0.5 fs to about -0.1 fs (vibration rectification).
  EXPECT_GT(mean_after - mean_before, 0.2 * fs) << mean_before << " -> " << mean_after;
  std::printf("vibration: az mean %.3f -> %.3f m/s^2, %zu of %zu values at a rail\n", mean_before, mean_after,
              at_full_scale, 3 * n);
}

TEST_F(DatasetFaults, DroppedMagnetometerRowsHaveEmptyMagFields) {
  const auto effects = inject({ImuDropMagFirstRows{100}});
  EXPECT_EQ(effects.at(0).changed, 100u);
  const auto before = lines_of(src("imu.csv")), after = lines_of(dst("imu.csv"));
  ASSERT_EQ(before.size(), after.size());
  const auto rb = flight_->imu(), ra = load_rows(dst("imu.csv"), dataset::kImuSchema);
  ASSERT_EQ(ra.size(), rb.size());
  for (std::size_t i = 0; i < 100; ++i) {
    dataset::ImuRow row{ra[i]};
    EXPECT_FALSE(ra[i].has(ic::mx) || ra[i].has(ic::my) || ra[i].has(ic::mz));
    EXPECT_FALSE(row.has_mag());
    EXPECT_TRUE(row.has_accel() && row.has_gyro() && row.has_temp());
    const auto fb = fields_of(before[i + 1]), fa = fields_of(after[i + 1]);
    for (std::size_t c : {ic::t, ic::ax, ic::ay, ic::az, ic::gx, ic::gy, ic::gz, ic::temp}) EXPECT_EQ(fa[c], fb[c]);
  }
  EXPECT_TRUE(dataset::ImuRow{ra[100]}.has_mag());
  EXPECT_EQ(std::vector(after.begin() + 101, after.end()), std::vector(before.begin() + 101, before.end()));
  EXPECT_EQ(after[0], before[0]);
  expect_copied("gps.nmea");
}

TEST_F(DatasetFaults, DropLeadingSecondsStartsEveryFileAfterTheCut) {
  const double cut = times().imu.first_s + 42.5;
  const auto effects = inject({DropLeadingSeconds{42.5}});
  EXPECT_EQ(effects.at(0).removed, expect_cut_at(cut, false));
  EXPECT_GE(load_rows(dst("imu.csv"), dataset::kImuSchema).front().t(), cut);
  EXPECT_GE(load_rows(dst("truth.csv"), dataset::kTruthSchema).front().t(), cut);
  const auto fixes = read_fixes(dst("gps.nmea"));
  ASSERT_FALSE(fixes.empty());
  EXPECT_GE(fixes.front().arrival_s, cut);
  expect_copied("meta.json");
}

TEST_F(DatasetFaults, KeepLeadingSecondsEndsEveryFileBeforeTheCut) {
  const double cut = times().imu.first_s + 42.5;
  const auto effects = inject({KeepLeadingSeconds{42.5}});
  EXPECT_EQ(effects.at(0).removed, expect_cut_at(cut, true));
  EXPECT_LT(load_rows(dst("imu.csv"), dataset::kImuSchema).back().t(), cut);
  const auto fixes = read_fixes(dst("gps.nmea"));
  ASSERT_FALSE(fixes.empty());
  EXPECT_LT(fixes.back().arrival_s, cut);
}

TEST_F(DatasetFaults, SeveralFaultsApplyInTheirOrder) {
  const DatasetTimes t = times();
  ImuClip clip;
  clip.start_s = t.imu.first_s + 10.0;
  clip.duration_s = 1.0;
  const auto effects = inject({GnssOutage{t.gps.first_s + 20.0, 5.0}, GnssGarbage{t.gps.first_s + 40.0, 5.0, 3},
                               ImuGap{t.imu.first_s + 30.0, 2.0}, clip, ImuDropMagFirstRows{10},
                               GnssPositionJump{t.gps.first_s + 40.0, 5.0, {100.0, 0.0, 0.0}}});
  ASSERT_EQ(effects.size(), 6u);
  EXPECT_GT(effects[0].removed, 60u);
  EXPECT_GT(effects[1].changed, 60u);
  EXPECT_EQ(effects[2].removed, 80u);
  EXPECT_EQ(effects[3].changed, 40u);
  EXPECT_EQ(effects[4].changed, 10u);
  EXPECT_EQ(effects[5].changed, 0u) << "the jump comes after the garbage: no valid sentence left to move";
  EXPECT_EQ(load_rows(dst("imu.csv"), dataset::kImuSchema).size(), flight_->imu().size() - 80);
  // The product's reader goes through the whole result, counting the garbage.
  dataset::GpsLogReader r;
  ASSERT_TRUE(r.open(dst("gps.nmea")));
  drivers::GpsFix fix;
  dataset::ReadStatus status;
  while ((status = r.next(fix)) == dataset::ReadStatus::Row)
    EXPECT_FALSE(in_window(fix.arrival_s, t.gps.first_s + 20.0, 5.0));
  EXPECT_EQ(status, dataset::ReadStatus::End);
  EXPECT_GE(r.corrupt(), effects[1].changed);
}

TEST_F(DatasetFaults, CrLfFilesKeepTheirLineEndings) {
  // The same flight with CR LF line endings and no LF after the last line.
  TempDir crlf;
  for (const char* f : {"imu.csv", "gps.nmea", "truth.csv", "meta.json"}) {
    std::string text;
    for (auto l : lines_of(src(f))) {
      l.pop_back();
      text += l + "\r\n";
    }
    text.resize(text.size() - 2);
    crlf.write(f, text);
  }
  const DatasetTimes t = dataset_times(crlf.path());
  EXPECT_EQ(t.imu.first_s, times().imu.first_s);
  ImuClip clip;
  clip.start_s = t.imu.first_s + 5.0;
  clip.duration_s = 2.0;
  inject_faults(
      crlf.path(), out_.path(),
      {GnssPositionJump{t.gps.first_s + 10.0, 10.0, {5.0, 5.0, 5.0}}, GnssGarbage{t.gps.first_s + 30.0, 10.0, 1},
       GnssOutage{t.gps.last_s - 5.0, 10.0}, clip, ImuGap{t.imu.first_s + 20.0, 1.0}});
  for (const char* f : {"imu.csv", "gps.nmea", "truth.csv"}) {
    const auto lines = lines_of(dst(f));
    ASSERT_GT(lines.size(), 2u);
    for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
      ASSERT_GE(lines[i].size(), 2u);
      ASSERT_EQ(lines[i].substr(lines[i].size() - 2), "\r\n") << f << " line " << i + 1;
    }
    EXPECT_EQ(lines.back().find_first_of("\r\n"), std::string::npos) << f << ": the last line has no terminator";
  }
  EXPECT_EQ(read_file(dst("truth.csv")), read_file(crlf.file("truth.csv")));
  load_rows(dst("imu.csv"), dataset::kImuSchema);
  read_gps_log(dst("gps.nmea"));
}
