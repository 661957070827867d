#include "firmware/host/calibration/progress_bar.hpp"

#include <algorithm>

namespace sinu::calibration {

namespace {
constexpr int kWidth = 30;
constexpr double kRedraw_s = 0.2;
}  // namespace

ProgressBar::ProgressBar(std::string label, double total, bool enabled)
    : label_(std::move(label)), total_(total), enabled_(enabled),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

void ProgressBar::update(double done) {
  if (!enabled_ || !(total_ > 0.0)) return;
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_draw_).count() < kRedraw_s && done < total_) return;
  last_draw_ = now;
  const double frac = std::clamp(done / total_, 0.0, 1.0);
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  const double eta = frac > 0.0 ? elapsed * (1.0 - frac) / frac : 0.0;
  const int filled = static_cast<int>(frac * kWidth);
  std::fprintf(stderr, "\r%s [%.*s%*s] %3.0f%% %5.1f s, ETA %5.1f s", label_.c_str(), filled,
               "##############################", kWidth - filled, "", 100.0 * frac, elapsed, eta);
  std::fflush(stderr);
}

void ProgressBar::finish() {
  if (!enabled_) return;
  update(total_);
  std::fputc('\n', stderr);
}

}  // namespace sinu::calibration
