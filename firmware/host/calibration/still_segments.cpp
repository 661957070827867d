#include "firmware/host/calibration/still_segments.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "firmware/host/calibration/bench_positions.hpp"

namespace sinu::calibration {

namespace {

struct Block {
  double accel_var = 0.0, gyro_var = 0.0;
  Eigen::Vector3d gyro_mean = Eigen::Vector3d::Zero();
};

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Variance summed over three axes [first, first + 3) of samples [b, e).
double triad_variance(const StaticSession& s, std::size_t first, std::size_t b, std::size_t e, Eigen::Vector3d& mean) {
  const auto n = static_cast<double>(e - b);
  double var = 0.0;
  for (std::size_t a = 0; a < 3; ++a) {
    const std::vector<double>& x = s.imu[first + a];
    double m = 0.0;
    for (std::size_t k = b; k < e; ++k) m += x[k];
    m /= n;
    double ss = 0.0;
    for (std::size_t k = b; k < e; ++k) ss += (x[k] - m) * (x[k] - m);
    var += ss / n;
    mean[static_cast<Eigen::Index>(a)] = m;
  }
  return var;
}

}  // namespace

std::vector<StillSegment> find_still_segments(const StaticSession& s, std::size_t input,
                                              const StillDetectorConfig& cfg) {
  std::vector<StillSegment> out;
  const std::size_t n = s.imu[0].size();
  if (n == 0 || !(s.dt_s > 0.0)) return out;
  const auto block = std::max<std::size_t>(2, static_cast<std::size_t>(std::lround(cfg.block_s / s.dt_s)));
  const std::size_t blocks = n / block;
  std::vector<Block> st(blocks);
  Eigen::Vector3d unused;
  for (std::size_t i = 0; i < blocks; ++i) {
    st[i].accel_var = triad_variance(s, 0, i * block, (i + 1) * block, unused);
    st[i].gyro_var = triad_variance(s, 3, i * block, (i + 1) * block, st[i].gyro_mean);
  }
  std::vector<double> av(blocks), gv(blocks), gm[3];
  for (std::size_t i = 0; i < blocks; ++i) {
    av[i] = st[i].accel_var;
    gv[i] = st[i].gyro_var;
    for (Eigen::Index a = 0; a < 3; ++a) gm[a].push_back(st[i].gyro_mean[a]);
  }
  const double accel_limit = std::max(cfg.variance_factor * median(av), cfg.min_accel_variance);
  const double gyro_limit = std::max(cfg.variance_factor * median(gv), cfg.min_gyro_variance);
  const Eigen::Vector3d rate_ref(median(gm[0]), median(gm[1]), median(gm[2]));
  const auto still = [&](std::size_t i) {
    return st[i].accel_var <= accel_limit && st[i].gyro_var <= gyro_limit &&
           (st[i].gyro_mean - rate_ref).norm() <= cfg.rate_limit_rad_s;
  };
  const auto trim = static_cast<std::size_t>(std::lround(cfg.trim_s / s.dt_s));
  const auto min_len = static_cast<std::size_t>(std::ceil(cfg.min_duration_s / s.dt_s));
  for (std::size_t i = 0; i < blocks;) {
    if (!still(i)) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < blocks && still(j)) ++j;
    // Trimmed at both ends, except at the session's own start and end (nothing to settle from).
    const std::size_t b = i * block + (i > 0 ? trim : 0);
    const std::size_t e = j * block - (j < blocks ? std::min(trim, j * block) : 0);
    i = j;
    if (e <= b || e - b < min_len) continue;
    StillSegment seg;
    seg.input = input;
    seg.begin = b;
    seg.end = e;
    seg.t_start_s = s.t0_s + static_cast<double>(b) * s.dt_s;
    seg.t_end_s = s.t0_s + static_cast<double>(e - 1) * s.dt_s;
    for (std::size_t a = 0; a < 3; ++a) {
      double fa = 0.0, ga = 0.0;
      for (std::size_t k = b; k < e; ++k) {
        fa += s.imu[a][k];
        ga += s.imu[3 + a][k];
      }
      seg.accel_mean_m_s2[static_cast<Eigen::Index>(a)] = fa / static_cast<double>(e - b);
      seg.gyro_mean_rad_s[static_cast<Eigen::Index>(a)] = ga / static_cast<double>(e - b);
    }
    out.push_back(seg);
  }
  return out;
}

std::size_t count_attitudes(const std::vector<StillSegment>& segments, std::vector<std::size_t>* group,
                            double max_angle_rad) {
  std::vector<Eigen::Vector3d> reps;
  if (group) group->assign(segments.size(), 0);
  const double cos_max = std::cos(max_angle_rad);
  for (std::size_t k = 0; k < segments.size(); ++k) {
    const Eigen::Vector3d u = segments[k].up_b();
    std::size_t g = 0;
    while (g < reps.size() && reps[g].dot(u) < cos_max) ++g;
    if (g == reps.size()) reps.push_back(u);
    if (group) (*group)[k] = g;
  }
  return reps.size();
}

std::string attitude_name(const Eigen::Vector3d& up_b) {
  const Eigen::Vector3d u = up_b.normalized();
  std::size_t best = 0;
  for (std::size_t k = 1; k < kMaxPositions; ++k)
    if (position_up_b(k).dot(u) > position_up_b(best).dot(u)) best = k;
  if (position_up_b(best).dot(u) >= std::cos(kSameAttitude_rad)) return position_name(best);
  return fmt::format("tilted ({:.2f}, {:.2f}, {:.2f}) up", u.x(), u.y(), u.z());
}

StaticSession slice_session(const StaticSession& s, std::size_t begin, std::size_t end) {
  StaticSession out;
  out.dataset = s.dataset;
  for (std::size_t a = 0; a < s.imu.size(); ++a)
    out.imu[a].assign(s.imu[a].begin() + static_cast<std::ptrdiff_t>(begin),
                      s.imu[a].begin() + static_cast<std::ptrdiff_t>(end));
  // The magnetometer has its own rows (often slower): its share of the span.
  const std::size_t n = s.imu[0].size();
  for (std::size_t a = 0; a < s.mag.size(); ++a) {
    const std::size_t m = s.mag[a].size();
    const std::size_t mb = n ? begin * m / n : 0, me = n ? end * m / n : 0;
    out.mag[a].assign(s.mag[a].begin() + static_cast<std::ptrdiff_t>(mb), s.mag[a].begin() + static_cast<std::ptrdiff_t>(me));
  }
  out.dt_s = s.dt_s;
  out.t0_s = s.t0_s + static_cast<double>(begin) * s.dt_s;
  out.duration_s = static_cast<double>(end - begin - 1) * s.dt_s;
  out.rows = end - begin;
  out.rows_without_imu = 0;
  out.gaps = 0;
  return out;
}

}  // namespace sinu::calibration
