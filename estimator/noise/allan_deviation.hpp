#pragma once
// Overlapping Allan deviation of a rate series (IEEE Std 952-1997, annex C):
// with theta(k) = dt * sum_{i<k} y(i) (angle for a gyro, velocity for an
// accelerometer), for cluster size m and tau = m dt
//   AVAR(tau) = 1 / (2 tau^2 (N + 1 - 2m)) sum_{k=0}^{N-2m} (theta(k+2m) - 2 theta(k+m) + theta(k))^2
// (N rate samples, N + 1 phase points theta(0..N)). One cumulative sum, then
// O(N) per tau; taus are spaced `per_octave` per factor of two, up to m = N/4
// (four clusters; the last points show it by their wide confidence interval).
//
// Confidence interval: chi-square with the equivalent degrees of freedom of
// the overlapping estimator for white rate noise (Howe, Allan & Barnes 1981):
//   edf = (3(N-1)/(2m) - 2(N-2)/N) * 4m^2 / (4m^2 + 5)
// and the chi-square quantiles by the Wilson-Hilferty approximation (relative
// error < 1% for edf > 3). White rate noise dominates where N and the bias
// instability are read; for rate random walk the true edf is smaller, so the
// interval there is optimistic (stated in docs/calibration.md).
#include <cstddef>
#include <span>
#include <vector>

namespace sinu::noise {

struct AllanPoint {
  double tau_s = 0.0;
  double adev = 0.0;
  double adev_low = 0.0, adev_high = 0.0;  // ~68% (1 sigma) interval
  double edf = 0.0;
  std::size_t cluster = 0;  // m
};

/// The mean is irrelevant to AVAR (it cancels); it is removed before the
/// cumulative sum only so theta stays small and exact in double precision.
std::vector<AllanPoint> overlapping_allan(std::span<const double> rate, double dt_s, int per_octave = 4);

}  // namespace sinu::noise
