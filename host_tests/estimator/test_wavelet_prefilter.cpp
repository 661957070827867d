// The wavelet denoiser in front of the INS (estimator/prefilter): each sample
// comes out Denoiser::kDelay samples later, with the values the standalone
// denoiser (checked against pywt in test_wavelet) gives, the time stamp,
// magnetometer and temperature of the instant it describes, nothing lost at
// the end, and no heap use per sample.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "estimator/prefilter/wavelet_prefilter.hpp"
#include "host_tests/support/alloc_counter.hpp"

namespace sinu::test {
namespace {

namespace wv = est::wavelet;
using Db4L3 = wv::WaveletDenoiser<wv::Db4, 3>;

std::vector<est::ImuSample> random_samples(int n) {
  std::mt19937 rng(5);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<est::ImuSample> v(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    est::ImuSample& s = v[static_cast<std::size_t>(k)];
    s.t_s = 100.0 + 0.025 * k;
    s.specific_force_b_m_s2 = {g(rng), g(rng), -9.8 + g(rng)};
    s.angular_rate_b_rad_s = {0.01 * g(rng), 0.01 * g(rng), 0.01 * g(rng)};
    s.mag_b_uT = {20.0 + g(rng), g(rng), 40.0 + g(rng)};
    s.has_mag = k % 2 == 0;
    s.temp_degC = 30.0 + 0.001 * k;
    s.has_temp = true;
  }
  return v;
}

TEST(WaveletPrefilter, DelaysEachSampleAndFiltersEachAxisLikeTheStandaloneDenoiser) {
  const std::vector<est::ImuSample> in = random_samples(600);
  auto pre = est::make_wavelet_prefilter(wv::WaveletKind::Db4, 3);
  ASSERT_EQ(pre->delay_samples(), Db4L3::kDelay);
  std::vector<Db4L3> ref;
  for (int c = 0; c < 3; ++c) ref.emplace_back(in[0].specific_force_b_m_s2(c));
  std::vector<est::ImuSample> out;
  std::vector<double> ref_fx;
  for (const est::ImuSample& s : in) {
    ref_fx.push_back(ref[0].step(s.specific_force_b_m_s2.x()));
    est::ImuSample o;
    if (pre->push(s, o)) out.push_back(o);
  }
  const std::size_t delay = static_cast<std::size_t>(Db4L3::kDelay);
  ASSERT_EQ(out.size(), in.size() - delay);
  for (std::size_t k = 0; k < out.size(); ++k) {
    // The output describes input k: its time, mag and temperature; the value is the
    // denoiser's output at step k + delay (y[n - delay]). Identical arithmetic: exact.
    EXPECT_EQ(out[k].t_s, in[k].t_s);
    EXPECT_EQ(out[k].has_mag, in[k].has_mag);
    EXPECT_EQ(out[k].mag_b_uT, in[k].mag_b_uT);
    EXPECT_EQ(out[k].temp_degC, in[k].temp_degC);
    EXPECT_EQ(out[k].specific_force_b_m_s2.x(), ref_fx[k + delay]);
  }
  est::ImuSample o;
  std::size_t drained = 0;
  while (pre->drain(o)) {
    EXPECT_EQ(o.t_s, in[out.size() + drained].t_s);
    ++drained;
  }
  EXPECT_EQ(drained, delay) << "every held sample comes out at the end";
}

TEST(WaveletPrefilter, PassesAConstantUnchangedAndRemovesAFastOscillation) {
  auto pre = est::make_wavelet_prefilter(wv::WaveletKind::Db4, 3);
  double max_const_err = 0.0, max_osc = 0.0;
  for (int k = 0; k < 800; ++k) {
    est::ImuSample s;
    s.t_s = 0.025 * k;
    // 9.81 constant on z; a 14 Hz vibration (engine band, paper Fig. 4) on x.
    s.specific_force_b_m_s2 = {0.5 * std::sin(2.0 * 3.141592653589793 * 14.0 * s.t_s), 0.0, -9.81};
    est::ImuSample o;
    if (pre->push(s, o) && k > 200) {
      max_const_err = std::max(max_const_err, std::abs(o.specific_force_b_m_s2.z() + 9.81));
      max_osc = std::max(max_osc, std::abs(o.specific_force_b_m_s2.x()));
    }
  }
  EXPECT_LT(max_const_err, 1e-9);  // unit DC gain (lifting reconstructs constants exactly, to rounding)
  EXPECT_LT(max_osc, 0.5 * 0.01);  // gain at most 0.0008 over 12-16 Hz (docs/wavelet.md): < 1% left
}

TEST(WaveletPrefilter, NoHeapUsePerSample) {
  const std::vector<est::ImuSample> in = random_samples(400);
  auto pre = est::make_wavelet_prefilter(wv::WaveletKind::Cdf97, 4);
  est::ImuSample o;
  AllocationScope scope;
  for (const est::ImuSample& s : in) pre->push(s, o);
  while (pre->drain(o)) {
  }
  EXPECT_EQ(scope.count(), 0u);
}

}  // namespace
}  // namespace sinu::test
