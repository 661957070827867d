#pragma once
// The lifting steps of one decomposition level, run pair by pair in a stream.
// Analysis runs W::steps in order; synthesis undoes them in reverse order.
// Each step keeps a shift register of its last R input pairs and outputs the
// pair look_ahead() pairs back, so a chain outputs pair m - chain_look_ahead()
// when pair m arrives. Fixed size, no allocation, O(steps) per pair.
#include <array>
#include <cstddef>
#include <utility>

#include "estimator/wavelet/lifting_step.hpp"

namespace sinu::est::wavelet {

struct EvenOdd {
  double even = 0.0;
  double odd = 0.0;
};

enum class LiftDirection { Analysis, Synthesis };

template <LiftingScheme W, LiftDirection Dir>
class LiftingChain {
 public:
  static constexpr std::size_t kSteps = W::steps.size();
  static constexpr std::size_t kRegister = chain_register_length<W>();
  static constexpr int kLookAhead = chain_look_ahead<W>();

  /// Pushes pair m, returns pair m - kLookAhead.
  EvenOdd push(EvenOdd pair) {
    return run<0>(pair);
  }

  void clear() {
    for (auto& r : even_) r.fill(0.0);
    for (auto& r : odd_) r.fill(0.0);
  }

 private:
  // Step k of the chain is step index(k) of W, applied with sign(k).
  static constexpr std::size_t index(std::size_t k) {
    return Dir == LiftDirection::Analysis ? k : kSteps - 1 - k;
  }
  static constexpr double kSign = Dir == LiftDirection::Analysis ? 1.0 : -1.0;

  template <std::size_t K>
  EvenOdd run(EvenOdd in) {
    if constexpr (K == kSteps) {
      return in;
    } else {
      constexpr LiftingStep step = W::steps[index(K)];
      auto& e = even_[K];
      auto& o = odd_[K];
      for (std::size_t r = 0; r + 1 < kRegister; ++r) {
        e[r] = e[r + 1];
        o[r] = o[r + 1];
      }
      e[kRegister - 1] = in.even;
      o[kRegister - 1] = in.odd;
      // Register slot of the pair being completed (index m - look_ahead).
      constexpr int current = static_cast<int>(kRegister) - 1 - step.look_ahead();
      const auto& src = step.kind == LiftKind::Predict ? e : o;
      double sum = 0.0;
      for (int t = 0; t < step.taps; ++t) {
        sum += step.coeff[static_cast<std::size_t>(t)] * src[static_cast<std::size_t>(current + step.first_offset + t)];
      }
      EvenOdd out{e[static_cast<std::size_t>(current)], o[static_cast<std::size_t>(current)]};
      if constexpr (step.kind == LiftKind::Predict) {
        out.odd += kSign * sum;
      } else {
        out.even += kSign * sum;
      }
      return run<K + 1>(out);
    }
  }

  std::array<std::array<double, kRegister>, kSteps> even_{};
  std::array<std::array<double, kRegister>, kSteps> odd_{};
};

}  // namespace sinu::est::wavelet
