// The simulator and the estimator speak one effect vocabulary: every effect
// `sinu simulate` can hide has estimator states of the same name and shape,
// so `diagnose` can name it and `--effects` can carry it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "estimator/ekf/effect_vocabulary.hpp"
#include "firmware/host/sim/effects.hpp"
#include "firmware/host/sim/effects/effect_list.hpp"

namespace sinu::sim {
namespace {

// The estimator's component layout a simulator value of this JSON shape needs.
bool shape_fits(const nlohmann::json& v, est::Components c) {
  if (v.is_number()) return c == est::Components::One;
  if (!v.is_array() || v.size() != 3) return false;
  if (v[0].is_number()) return c == est::Components::Xyz;
  // 3x3: soft iron is symmetric, misalignments have no diagonal, g-sensitivity is full.
  return c == est::Components::Symmetric || c == est::Components::OffDiagonal || c == est::Components::Matrix;
}

TEST(EffectVocabulary, EverySimulatedEffectHasEstimatorStatesOfTheSameNameAndShape) {
  Rng rng(7, RngStream::Effects);
  const nlohmann::json all = effects_to_json(draw_random_effects(kEffectNames.size(), rng));
  ASSERT_EQ(all.size(), kEffectNames.size()) << "draw_random_effects(all) draws every effect";
  for (const auto& [name, value] : all.items()) {
    SCOPED_TRACE(name);
    est::Effect e{};
    ASSERT_TRUE(est::effect_from_name(name.c_str(), name.size(), e)) << "no estimator states for " << name;
    EXPECT_TRUE(shape_fits(value, est::spec(e).components)) << value.dump();
    // diagnose tries it, or the model always has it (the navigator carries the
    // hard iron whenever there is a magnetometer).
    EXPECT_TRUE(est::spec(e).diagnose_candidate || e == est::Effect::MagHardIron) << "diagnose would never try it";
  }
}

TEST(EffectVocabulary, EveryEstimatorEffectHasAUnitAPriorAndComponentNames) {
  for (const est::EffectSpec& s : est::kEffects) {
    SCOPED_TRACE(s.name);
    EXPECT_GT(s.initial_sigma, 0.0);
    EXPECT_GE(s.random_walk, 0.0);
    EXPECT_GT(std::string(s.unit).size(), 0u);
    const Eigen::Index n = est::component_count(s.components);
    for (Eigen::Index i = 0; i < n; ++i) {
      const std::string c = est::effect_component_name(s.effect, i);
      EXPECT_EQ(c.empty(), n == 1);
      for (Eigen::Index j = 0; j < i; ++j) EXPECT_NE(c, est::effect_component_name(s.effect, j)) << "duplicate names";
    }
  }
}

}  // namespace
}  // namespace sinu::sim
