#pragma once
// Sample autocorrelation r(k), k = 0..max_lag, of a series that already has its
// mean removed (nothing is subtracted here, as MATLAB's xcorr).
//   biased:   r(k) = 1/N     * sum_{n=k}^{N-1} x(n) x(n-k)   (positive semi-definite;
//                                                               what Yule-Walker uses)
//   unbiased: r(k) = 1/(N-k) * sum_{n=k}^{N-1} x(n) x(n-k)
// Short lag ranges are summed directly (O(N * max_lag)); long ones go through
// Eigen's FFT (O(N log N)), zero-padded to >= 2N so the circular product is
// the linear one.
#include <cstddef>
#include <span>
#include <vector>

namespace sinu::noise {

enum class AcfScale { Biased, Unbiased };

std::vector<double> autocorrelation(std::span<const double> x, std::size_t max_lag, AcfScale scale);

/// The FFT path, exposed so tests can compare it with the direct sum.
std::vector<double> autocorrelation_fft(std::span<const double> x, std::size_t max_lag, AcfScale scale);
std::vector<double> autocorrelation_direct(std::span<const double> x, std::size_t max_lag, AcfScale scale);

}  // namespace sinu::noise
