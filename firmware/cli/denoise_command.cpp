// sinu denoise --in DATASET --out DIR [--wavelet W] [--levels N]: the paper's
// wavelet pre-filter applied to a dataset. imu.csv's accelerometer and gyro
// columns are replaced by their level-N approximation, time-aligned: the row
// stamped t holds the filter output for the input sample at t (the filter's
// constant delay is removed). Magnetometer, temperature and every other file
// are copied unchanged.
//
// Ends and holes: the filter is primed with the first sample (as if it had
// been held forever before t0) and flushed with the last one (held for
// `delay` more samples), so the first and last `delay` rows see a constant
// extension of the signal. An empty accel/gyro field stays empty in the
// output; the filter is fed the channel's previous value there (counted).
// Time gaps are counted and reported: the filter assumes even sampling.
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

#include "estimator/wavelet/denoiser_select.hpp"
#include "firmware/cli/command.hpp"
#include "firmware/cli/exit_codes.hpp"
#include "firmware/host/dataset/dataset_paths.hpp"
#include "firmware/host/dataset/imu_csv.hpp"

namespace sinu::cli {

namespace {

namespace fs = std::filesystem;
namespace wv = sinu::est::wavelet;

struct DenoiseOptions {
  std::string in, out;
  std::string wavelet = wv::wavelet_name(wv::kDefaultWavelet);
  int levels = wv::kDefaultLevels;
};

constexpr std::size_t kFirstChannel = dataset::imu_col::ax;  // ax ay az gx gy gz
constexpr std::size_t kChannels = 6;

struct DenoiseStats {
  std::size_t rows = 0;
  std::size_t held_fields = 0;  // empty accel/gyro fields bridged by the previous value
  std::size_t time_gaps = 0;    // intervals longer than 1.5x the first one
  int delay = 0;
};

/// Streams imu.csv through one denoiser per channel. False: error printed.
template <class Denoiser>
bool denoise_imu(dataset::CsvReader& reader, dataset::CsvWriter& writer, DenoiseStats& stats) {
  constexpr std::size_t kDelay = static_cast<std::size_t>(Denoiser::kDelay);
  stats.delay = Denoiser::kDelay;
  std::array<Denoiser, kChannels> filters;
  std::array<double, kChannels> last{};
  std::vector<dataset::CsvRow> pending(kDelay + 1);  // rows waiting for their output
  double first_dt = 0.0, prev_t = 0.0;

  // Feeds input i (a row, or the held last values when row is null) and
  // writes row i - delay if it exists.
  auto feed = [&](std::size_t i, const dataset::CsvRow* row) {
    std::array<double, kChannels> y{};
    for (std::size_t c = 0; c < kChannels; ++c) {
      if (row && row->has(kFirstChannel + c)) {
        last[c] = row->value[kFirstChannel + c];
      } else if (row) {
        ++stats.held_fields;
      }
      y[c] = filters[c].step(last[c]);
    }
    if (row) pending[i % (kDelay + 1)] = *row;
    if (i < kDelay) return true;
    dataset::CsvRow& out = pending[(i - kDelay) % (kDelay + 1)];
    for (std::size_t c = 0; c < kChannels; ++c) {
      if (out.has(kFirstChannel + c)) out.value[kFirstChannel + c] = y[c];
    }
    if (!writer.write(out)) {
      std::fprintf(stderr, "%s\n", writer.error().to_string().c_str());
      return false;
    }
    return true;
  };

  dataset::CsvRow row;
  for (;;) {
    const dataset::ReadStatus status = reader.next(row);
    if (status == dataset::ReadStatus::Error) {
      std::fprintf(stderr, "%s\n", reader.error().to_string().c_str());
      return false;
    }
    if (status == dataset::ReadStatus::End) break;
    const std::size_t i = stats.rows++;
    if (i == 0) {  // prime with the first sample: no start-up ramp
      for (std::size_t c = 0; c < kChannels; ++c) {
        last[c] = row.has(kFirstChannel + c) ? row.value[kFirstChannel + c] : 0.0;
        filters[c].reset(last[c]);
      }
    } else {
      const double dt = row.t() - prev_t;
      if (i == 1) first_dt = dt;
      if (dt > 1.5 * first_dt) ++stats.time_gaps;
    }
    prev_t = row.t();
    if (!feed(i, &row)) return false;
  }
  // Flush: hold the last sample for `delay` more inputs.
  for (std::size_t i = stats.rows; i < stats.rows + kDelay; ++i) {
    if (!feed(i, nullptr)) return false;
  }
  return true;
}

bool copy_other_files(const fs::path& in, const fs::path& out) {
  std::error_code ec;
  for (const fs::directory_entry& entry : fs::directory_iterator(in, ec)) {
    if (!entry.is_regular_file() || entry.path().filename() == "imu.csv") continue;
    fs::copy_file(entry.path(), out / entry.path().filename(), fs::copy_options::overwrite_existing, ec);
    if (ec) {
      std::fprintf(stderr, "sinu denoise: cannot copy %s: %s\n", entry.path().string().c_str(), ec.message().c_str());
      return false;
    }
  }
  if (ec) {
    std::fprintf(stderr, "sinu denoise: cannot list %s: %s\n", in.string().c_str(), ec.message().c_str());
    return false;
  }
  return true;
}

int denoise(const DenoiseOptions& o) {
  const dataset::DatasetPaths in{o.in}, out{o.out};
  std::error_code ec;
  if (!fs::is_directory(in.dir)) {
    std::fprintf(stderr, "sinu denoise: %s: not a dataset folder\n", o.in.c_str());
    return kExitFailure;
  }
  fs::create_directories(out.dir, ec);
  if (ec || !fs::is_directory(out.dir)) {
    std::fprintf(stderr, "sinu denoise: cannot create %s: %s\n", o.out.c_str(), ec.message().c_str());
    return kExitFailure;
  }
  if (fs::equivalent(in.dir, out.dir, ec)) {
    std::fprintf(stderr, "sinu denoise: --out must differ from --in (%s)\n", o.out.c_str());
    return kExitUsage;
  }
  dataset::CsvReader reader(dataset::kImuSchema);
  if (!reader.open(in.imu())) {
    std::fprintf(stderr, "%s\n", reader.error().to_string().c_str());
    return kExitFailure;
  }
  dataset::CsvWriter writer(dataset::kImuSchema);
  dataset::set_imu_formats(writer);
  if (!writer.open(out.imu())) {
    std::fprintf(stderr, "%s\n", writer.error().to_string().c_str());
    return kExitFailure;
  }
  const wv::WaveletKind kind = *wv::parse_wavelet(o.wavelet);  // validated by CLI11
  DenoiseStats stats;
  const bool ok = wv::with_denoiser(kind, o.levels, [&]<class Denoiser>() {
    return denoise_imu<Denoiser>(reader, writer, stats);
  });
  if (!ok) return kExitFailure;
  if (!writer.close()) {
    std::fprintf(stderr, "%s\n", writer.error().to_string().c_str());
    return kExitFailure;
  }
  if (!copy_other_files(in.dir, out.dir)) return kExitFailure;
  std::fprintf(stderr,
               "sinu denoise: %zu rows, %s level %d, delay %d samples removed from t; first and last %d rows "
               "filtered against the held first/last sample\n",
               stats.rows, o.wavelet.c_str(), o.levels, stats.delay, stats.delay);
  if (stats.held_fields > 0) {
    std::fprintf(stderr, "sinu denoise: %zu empty accel/gyro fields kept empty (filter fed the previous value)\n",
                 stats.held_fields);
  }
  if (stats.time_gaps > 0) {
    std::fprintf(stderr,
                 "sinu denoise: warning: %zu time gaps longer than 1.5 sample periods; the filter treats samples as "
                 "evenly spaced\n",
                 stats.time_gaps);
  }
  return kExitOk;
}

}  // namespace

void add_denoise_command(CLI::App& app, Action& action) {
  auto opts = std::make_shared<DenoiseOptions>();
  CLI::App* sub = app.add_subcommand("denoise", "Wavelet-denoise a dataset's accelerometer and gyro channels");
  sub->add_option("--in", opts->in, "Input dataset folder")->required();
  sub->add_option("--out", opts->out, "Output dataset folder (created; files in it are overwritten)")->required();
  sub->add_option("--wavelet", opts->wavelet, "Mother wavelet (default db4)")
      ->check(CLI::IsMember({"haar", "db2", "db4", "cdf53", "cdf97"}));
  sub->add_option("--levels", opts->levels, "Decomposition levels, 1-6 (default 3: 2.5 Hz at 40 Hz)")
      ->check(CLI::Range(1, wv::kMaxLevels));
  sub->footer("Keeps the level-N approximation, drops every detail (paper section 2); the output rows keep "
              "their t: the filter's delay is removed.");
  sub->callback([&action, opts] { action = [opts] { return denoise(*opts); }; });
}

}  // namespace sinu::cli
