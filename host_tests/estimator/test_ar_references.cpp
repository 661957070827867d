// AR(1..10) by Yule-Walker, Covariance and Burg against independent references
// on the same series: Octave signal's aryule and arburg, and a least-squares
// covariance method (QR on the data matrix) written in tools/gen_ar_fixtures.m.
// The fixtures are text files in host_tests/fixtures/noise/, so no Octave is
// needed here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "estimator/noise/ar_burg.hpp"
#include "estimator/noise/ar_covariance.hpp"
#include "estimator/noise/ar_yule_walker.hpp"

namespace {

using sinu::noise::ArModel;

const std::string kDir = std::string(SINU_SOURCE_DIR) + "/host_tests/fixtures/noise/";

std::vector<double> read_series(const std::string& name) {
  std::ifstream in(kDir + name + "_series.txt");
  std::vector<double> x;
  double v;
  while (in >> v) x.push_back(v);
  return x;
}

// method -> order -> model
std::map<std::string, std::map<std::size_t, ArModel>> read_expected(const std::string& name) {
  std::ifstream in(kDir + name + "_expected.txt");
  std::map<std::string, std::map<std::size_t, ArModel>> out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    std::string method;
    std::size_t p = 0;
    ArModel m;
    s >> method >> p >> m.variance;
    double a;
    while (s >> a) m.a.push_back(a);
    out[method][p] = m;
  }
  return out;
}

// 1e-9 relative: coefficients relative to the largest |a_i| (a0 = 1, so the
// scale is >= 1 and a near-zero a_i is not judged relative to itself), the
// variance relative to itself. The references use different algorithms
// (Octave's levinson, QR least squares), so agreement is at rounding level
// times the conditioning of these short, well-conditioned series (~1e-13).
constexpr double kRelTol = 1e-9;

void expect_same(const ArModel& got, const ArModel& ref, const std::string& what) {
  ASSERT_EQ(got.a.size(), ref.a.size()) << what;
  double scale = 0.0;
  for (double v : ref.a) scale = std::max(scale, std::abs(v));
  for (std::size_t i = 0; i < ref.a.size(); ++i) {
    EXPECT_LE(std::abs(got.a[i] - ref.a[i]), kRelTol * scale) << what << " a" << i;
  }
  EXPECT_LE(std::abs(got.variance - ref.variance), kRelTol * ref.variance) << what << " variance";
}

class ArReference : public ::testing::TestWithParam<const char*> {};

TEST_P(ArReference, AllMethodsAllOrdersMatchIndependentReferences) {
  const std::string name = GetParam();
  const std::vector<double> x = read_series(name);
  ASSERT_EQ(x.size(), 2000u) << "fixture " << name << " missing: run octave-cli tools/gen_ar_fixtures.m";
  const auto expected = read_expected(name);
  ASSERT_EQ(expected.size(), 3u);
  const std::map<std::string, std::vector<ArModel>> got = {
      {"yule_walker", sinu::noise::ar_yule_walker(x, 10)},
      {"covariance", sinu::noise::ar_covariance(x, 10)},
      {"burg", sinu::noise::ar_burg(x, 10)},
  };
  for (const auto& [method, models] : got) {
    ASSERT_EQ(models.size(), 10u) << method;
    for (std::size_t p = 1; p <= 10; ++p) {
      expect_same(models[p - 1], expected.at(method).at(p), name + " " + method + " p=" + std::to_string(p));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Fixtures, ArReference, ::testing::Values("ar2_periodic", "ar4_mixed", "ar1_offset"));

TEST(ArConventions, MatlabSignAndNoImplicitDemeaning) {
  // ar1_offset is x(n) = 0.95 x(n-1) + e(n), plus 0.5. MATLAB's convention
  // writes it a = [1, -0.95]: a1 must come out negative (statsmodels and the
  // arburg help text use the opposite sign).
  const std::vector<double> x = read_series("ar1_offset");
  const auto burg = sinu::noise::ar_burg(x, 1);
  ASSERT_EQ(burg.size(), 1u);
  EXPECT_LT(burg[0].a[1], -0.9);
  // Without demeaning the offset inflates the lag-0 power x'x/N above the
  // demeaned variance; the fitters must not silently subtract the mean (the
  // caller does, and reports the mean as turn-on bias).
  double mean = 0.0;
  for (double v : x) mean += v;
  mean /= static_cast<double>(x.size());
  std::vector<double> centred = x;
  for (double& v : centred) v -= mean;
  const auto burg_centred = sinu::noise::ar_burg(centred, 1);
  EXPECT_GT(std::abs(burg_centred[0].a[1] - burg[0].a[1]), 1e-4);
}

TEST(ArInput, TooShortSeriesGivesNoModelsInsteadOfGarbage) {
  const std::vector<double> x{1.0, 2.0, 3.0};
  EXPECT_TRUE(sinu::noise::ar_burg(x, 10).empty());
  EXPECT_TRUE(sinu::noise::ar_covariance(x, 10).empty());
  EXPECT_TRUE(sinu::noise::ar_yule_walker(x, 10).empty());
  const std::vector<double> zeros(100, 0.0);
  EXPECT_TRUE(sinu::noise::ar_yule_walker(zeros, 3).empty());
  EXPECT_TRUE(sinu::noise::ar_burg(zeros, 3).empty());
}

}  // namespace
