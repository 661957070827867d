// ns per sample per channel of the streaming wavelet denoiser (issue 4).
#include <benchmark/benchmark.h>

#include <array>
#include <cmath>
#include <vector>

#include "estimator/wavelet/wavelet_bases.hpp"
#include "estimator/wavelet/wavelet_denoiser.hpp"

namespace {

using namespace sinu::est::wavelet;

std::vector<double> input() {
  std::vector<double> x(4096);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = -9.8 + 0.1 * std::sin(0.37 * static_cast<double>(i));
  return x;
}

// One channel: items = samples.
template <class W, int L>
void BM_Denoise1(benchmark::State& state) {
  const std::vector<double> x = input();
  WaveletDenoiser<W, L> d(-9.8);
  for (auto _ : state) {
    for (double v : x) benchmark::DoNotOptimize(d.step(v));
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(x.size()));
}

// Six channels (ax..gz) as sinu denoise runs them: items = samples x channels.
template <class W, int L>
void BM_Denoise6(benchmark::State& state) {
  const std::vector<double> x = input();
  std::array<WaveletDenoiser<W, L>, 6> d;
  for (auto _ : state) {
    for (double v : x) {
      for (auto& c : d) benchmark::DoNotOptimize(c.step(v));
    }
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(x.size()) * 6);
}

BENCHMARK(BM_Denoise1<Db4, 3>);
BENCHMARK(BM_Denoise6<Db4, 3>);
BENCHMARK(BM_Denoise1<Haar, 3>);
BENCHMARK(BM_Denoise1<Cdf97, 3>);
BENCHMARK(BM_Denoise1<Db4, 6>);

}  // namespace

BENCHMARK_MAIN();
