#include "firmware/host/sim/rng.hpp"

#include <cmath>

namespace sinu::sim {

namespace {
std::uint64_t splitmix64(std::uint64_t& x) {
  x += 0x9E3779B97F4A7C15ull;
  std::uint64_t z = x;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
}  // namespace

Rng::Rng(std::uint64_t seed, RngStream stream) {
  std::uint64_t x = seed * 0x2545F4914F6CDD1Dull ^ static_cast<std::uint64_t>(stream) * 0x9E3779B97F4A7C15ull;
  for (auto& s : s_) s = splitmix64(x);
}

std::uint64_t Rng::next_u64() {
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double Rng::uniform() { return static_cast<double>(next_u64() >> 11) * 0x1.0p-53; }

double Rng::signed_uniform(double lo, double hi) {
  const double m = uniform(lo, hi);
  return (next_u64() >> 63) ? -m : m;
}

double Rng::log_uniform(double lo, double hi) { return lo * std::exp(uniform() * std::log(hi / lo)); }

double Rng::normal() {
  if (has_spare_) {
    has_spare_ = false;
    return spare_;
  }
  double u = 0.0, v = 0.0, s = 0.0;
  do {
    u = 2.0 * uniform() - 1.0;
    v = 2.0 * uniform() - 1.0;
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double k = std::sqrt(-2.0 * std::log(s) / s);
  spare_ = v * k;
  has_spare_ = true;
  return u * k;
}

std::uint64_t Rng::below(std::uint64_t n) { return n == 0 ? 0 : next_u64() % n; }

}  // namespace sinu::sim
