#include "estimator/wavelet/denoiser_select.hpp"

namespace sinu::est::wavelet {

namespace {
struct Named {
  WaveletKind kind;
  std::string_view name;
};
constexpr Named kNames[] = {{WaveletKind::Haar, "haar"},
                            {WaveletKind::Db2, "db2"},
                            {WaveletKind::Db4, "db4"},
                            {WaveletKind::Cdf53, "cdf53"},
                            {WaveletKind::Cdf97, "cdf97"}};
}  // namespace

std::optional<WaveletKind> parse_wavelet(std::string_view name) {
  for (const Named& n : kNames) {
    if (n.name == name) return n.kind;
  }
  return std::nullopt;
}

const char* wavelet_name(WaveletKind kind) {
  for (const Named& n : kNames) {
    if (n.kind == kind) return n.name.data();
  }
  return "db4";
}

}  // namespace sinu::est::wavelet
