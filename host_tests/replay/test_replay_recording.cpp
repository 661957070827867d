// sinu replay --in RAW: a raw HAL recording through HAL -> drivers ->
// estimator gives the same navigation output, bit for bit, as the dataset
// it converts to; the comparison notices a one-sample difference; truncated
// and foreign files; the allocation count does not grow with the flight.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "firmware/host/replay/replay_files.hpp"
#include "host_tests/support/alloc_counter.hpp"
#include "host_tests/support/read_json.hpp"
#include "host_tests/support/run_process.hpp"
#include "host_tests/support/shared_data.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace sinu::test {
namespace {

void spit(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

std::size_t count_lines(const std::string& text) { return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')); }

/// Simulated flight DIR, DIR -> RAW (emulator + NMEA bytes), RAW -> DIR2 (drivers).
struct Flight {
  std::string dir, raw, dir2;
};

Flight make_flight(const TempDir& tmp, int seconds, int seed, const std::string& gps_rate_hz = "5") {
  Flight f{tmp.file("flight"), tmp.file("flight.raw"), tmp.file("flight2")};
  auto r = run_sinu({"simulate", "flight", "--duration", std::to_string(seconds), "--seed", std::to_string(seed),
                     "--gps-rate", gps_rate_hz, "--out", f.dir});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_sinu({"convert", f.dir, f.raw});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  r = run_sinu({"convert", f.raw, f.dir2});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return f;
}

ProcessResult replay(const std::string& in, const std::string& out, const std::string& truth,
                     const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"replay", "--in", in, "--out", out, "--model", "ar", "--effects",
                                   "accel_bias,gyro_bias", "--truth", truth, "--quiet"};
  args.insert(args.end(), extra.begin(), extra.end());
  return run_sinu(args);
}

class ReplayRecording : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    tmp_ = new TempDir;
    flight_ = make_flight(*tmp_, 300, 3);
  }
  static void TearDownTestSuite() {
    delete tmp_;
    tmp_ = nullptr;
  }
  static std::string out(const std::string& name) { return tmp_->file(name); }
  static std::string truth() { return flight_.dir + "/truth.csv"; }
  static TempDir* tmp_;
  static Flight flight_;
};
TempDir* ReplayRecording::tmp_ = nullptr;
Flight ReplayRecording::flight_;

TEST_F(ReplayRecording, RawAndTheDatasetItConvertsToGiveTheSameBits) {
  const std::string a = out("from_raw"), b = out("from_dir2");
  auto r = replay(flight_.raw, a, truth());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "") << "a whole recording converted from a dataset replays without a note";
  r = replay(flight_.dir2, b, truth());
  ASSERT_EQ(r.exit_code, 0) << r.err;

  const std::string nav_a = read_file(a + "/nav.csv"), innov_a = read_file(a + "/innovations.csv");
  // Something to compare: 10 Hz rows from alignment (about a minute in) to the end, GPS innovations.
  EXPECT_GT(count_lines(nav_a), 2000u);
  EXPECT_GT(count_lines(innov_a), 1000u);
  EXPECT_EQ(nav_a, read_file(b + "/nav.csv"));
  EXPECT_EQ(innov_a, read_file(b + "/innovations.csv"));
  // summary.json prints doubles in shortest round-trip form, so equal text is
  // equal final state (effects, sensor errors) and metrics to the last bit.
  nlohmann::json sa = read_json(a + "/summary.json"), sb = read_json(b + "/summary.json");
  EXPECT_EQ(sa["dataset"], flight_.raw);
  EXPECT_EQ(sb["dataset"], flight_.dir2);
  EXPECT_TRUE(sa["aligned"].get<bool>());
  EXPECT_GT(sa["rmse"]["truth_points"].get<int>(), 2000) << "--truth applies to a recording";
  EXPECT_GT(sa["gnss"]["used"].get<int>(), 1000);
  sa.erase("dataset");
  sb.erase("dataset");
  EXPECT_EQ(sa.dump(), sb.dump());
}

// A 1 Hz receiver: an epoch the fix assembler closes only when the next one
// starts (the first, and those after a corrupt sentence) reaches the board
// loop 1 s after its arrival, beyond the navigator's horizon. A recording
// replays what the board did: those fixes are late (counted, not fused),
// where a dataset replay, which knows every arrival up front, fuses them.
// Everything else is the same epochs, and the solutions agree.
TEST(ReplayRecordingSlowGps, OneHertzGpsEpochsCompletedLateAreLateAsOnTheBoard) {
  TempDir tmp;
  const Flight f = make_flight(tmp, 300, 3, "1");
  const std::string a = tmp.file("a"), b = tmp.file("b");
  auto r = replay(f.raw, a, f.dir + "/truth.csv");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  ASSERT_EQ(replay(f.dir2, b, f.dir + "/truth.csv").exit_code, 0);
  const nlohmann::json sa = read_json(a + "/summary.json"), sb = read_json(b + "/summary.json");
  EXPECT_GT(sa["gnss"]["used"].get<int>(), 200);
  EXPECT_EQ(sa["gnss"]["used"], sb["gnss"]["used"]) << "the same epochs reach the navigator";
  EXPECT_EQ(sb["gnss"]["late"].get<int>(), 0);
  EXPECT_GE(sa["gnss"]["late"].get<int>(), 1) << "the first epoch completes a second late";
  EXPECT_LE(sa["gnss"]["late"].get<int>(), 5) << "only epochs closed by the next one (first, after corruption)";
  // One or two missing 1 Hz fixes move the solution by much less than its error (~1 m).
  EXPECT_NEAR(sa["rmse"]["pos_h_m"].get<double>(), sb["rmse"]["pos_h_m"].get<double>(), 0.1);
}

// The real drive (100 Hz IMU, 4 Hz GPS from a real receiver): converted to a
// recording, replayed through the drivers, the same bits as its conversion back.
TEST(ReplayRecordingRealDrive, SameBitsAsTheDatasetItConvertsTo) {
  SINU_REQUIRE_SHARED(drive, "data/real/drive_0708");
  TempDir tmp;
  const std::string raw = tmp.file("drive.raw"), dir2 = tmp.file("drive2");
  ASSERT_EQ(run_sinu({"convert", drive, raw}).exit_code, 0);
  ASSERT_EQ(run_sinu({"convert", raw, dir2}).exit_code, 0);
  const std::string a = tmp.file("a"), b = tmp.file("b");
  ASSERT_EQ(replay(raw, a, drive + "/truth.csv").exit_code, 0);
  ASSERT_EQ(replay(dir2, b, drive + "/truth.csv").exit_code, 0);
  const std::string nav = read_file(a + "/nav.csv");
  EXPECT_GT(count_lines(nav), 3000u);
  EXPECT_EQ(nav, read_file(b + "/nav.csv"));
  EXPECT_EQ(read_file(a + "/innovations.csv"), read_file(b + "/innovations.csv"));
  nlohmann::json sa = read_json(a + "/summary.json"), sb = read_json(b + "/summary.json");
  sa.erase("dataset");
  sb.erase("dataset");
  EXPECT_EQ(sa.dump(), sb.dump());
}

TEST_F(ReplayRecording, TheComparisonSeesAOneSampleDifferenceAndAnOptionChange) {
  const std::string base = out("base");
  ASSERT_EQ(replay(flight_.raw, base, truth()).exit_code, 0);
  const std::string nav = read_file(base + "/nav.csv");

  // DIR2 with one accelerometer value changed by 0.01 m/s^2 (4 LSB at 8 g)
  // in one row, 100 s into the flight.
  const std::string edited = out("edited");
  std::filesystem::copy(flight_.dir2, edited, std::filesystem::copy_options::recursive);
  std::istringstream in(read_file(edited + "/imu.csv"));
  std::ostringstream os;
  std::string line;
  for (int row = 0; std::getline(in, line); ++row) {
    if (row == 4000) {
      const std::size_t c1 = line.find(','), c2 = line.find(',', c1 + 1);
      const double ax = std::stod(line.substr(c1 + 1, c2 - c1 - 1));
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.17g", ax + 0.01);
      line = line.substr(0, c1 + 1) + buf + line.substr(c2);
    }
    os << line << "\n";
  }
  spit(edited + "/imu.csv", os.str());
  const std::string d = out("edited_out");
  ASSERT_EQ(replay(edited, d, truth()).exit_code, 0);
  EXPECT_NE(nav, read_file(d + "/nav.csv"));

  const std::string l = out("latency");
  ASSERT_EQ(replay(flight_.raw, l, truth(), {"--gps-latency", "0.08"}).exit_code, 0);  // default 0.05
  EXPECT_NE(nav, read_file(l + "/nav.csv"));
}

TEST_F(ReplayRecording, ATruncatedRecordingReplaysUpToItsLastWholeRecordAndSaysSo) {
  const std::string whole = out("whole");
  ASSERT_EQ(replay(flight_.raw, whole, truth()).exit_code, 0);
  const std::string bytes = read_file(flight_.raw);
  const std::string cut = out("cut.raw");
  spit(cut, bytes.substr(0, bytes.size() / 2 + 7));  // mid-record, most likely; the CRC catches it either way
  const std::string part = out("part");
  const auto r = replay(cut, part, truth());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("truncated"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(cut), std::string::npos) << r.err;
  const auto s_whole = read_json(whole + "/summary.json"), s_part = read_json(part + "/summary.json");
  const auto n_whole = s_whole["imu_samples"].get<std::uint64_t>(), n_part = s_part["imu_samples"].get<std::uint64_t>();
  // About half the samples (the GPS bytes make the records uneven in size).
  EXPECT_GT(n_part, n_whole / 4);
  EXPECT_LT(n_part, n_whole * 3 / 4);
  // Up to the cut the output is the whole recording's: all rows but the last
  // second (the navigator's 0.3 s horizon and the GPS epoch the cut lost
  // are flushed differently) are identical.
  std::istringstream a(read_file(whole + "/nav.csv")), b(read_file(part + "/nav.csv"));
  std::vector<std::string> rows_part;
  for (std::string l; std::getline(b, l);) rows_part.push_back(l);
  ASSERT_GT(rows_part.size(), 20u);
  std::string la;
  for (std::size_t i = 0; i + 10 < rows_part.size(); ++i) {
    ASSERT_TRUE(static_cast<bool>(std::getline(a, la)));
    ASSERT_EQ(la, rows_part[i]) << "nav.csv line " << i + 1;
  }
}

TEST(ReplayRecordingInput, AFileThatIsNoRecordingIsARuntimeErrorNamingIt) {
  TempDir tmp;
  const std::string text = tmp.file("notes.txt");
  spit(text, "t,ax,ay,az\n1,2,3,4\n");
  auto r = run_sinu({"replay", "--in", text, "--out", tmp.file("o")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(text), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("not a sinu raw recording"), std::string::npos) << r.err;
  const std::string missing = tmp.file("nowhere.raw");
  r = run_sinu({"replay", "--in", missing, "--out", tmp.file("o2")});
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find(missing), std::string::npos) << r.err;
}

// The replay of a recording (loaded whole, then run through the board loop,
// the drivers and the navigator) allocates a bounded number of times.
TEST(ReplayRecordingAlloc, AllocationCountDoesNotGrowWithFlightLength) {
  std::uint64_t counts[2] = {0, 0};
  const int seconds[2] = {300, 1200};
  for (int i = 0; i < 2; ++i) {
    TempDir sub;
    const Flight f = make_flight(sub, seconds[i], 5);
    replay::ReplayOptions opt;
    opt.in_dir = f.raw;
    const std::string out_dir = sub.file("out");
    opt.unit.calib.kind = est::NoiseModelKind::AutoRegressive;
    replay::ReplayResult totals;
    std::string error;
    AllocationScope scope;
    ASSERT_TRUE(replay::replay_to_folder(opt, out_dir, 10.0, totals, error)) << error;
    counts[i] = scope.count();
    EXPECT_TRUE(totals.aligned);
    EXPECT_EQ(totals.note, "");
  }
  std::printf("allocations: %llu (300 s), %llu (1200 s)\n", static_cast<unsigned long long>(counts[0]),
              static_cast<unsigned long long>(counts[1]));
  // Loading the recording grows two vectors geometrically: 4x the length is
  // 2 more doublings each; slack 16 as in ReplayAlloc.
  EXPECT_LE(counts[1], counts[0] + 16);
  EXPECT_LT(counts[1], 2000u);
}

}  // namespace
}  // namespace sinu::test
