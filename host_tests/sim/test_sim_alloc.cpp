// The simulator streams rows to the writers without heap allocation per row:
// a session twice as long makes exactly as many allocations.
#include <gtest/gtest.h>

#include "firmware/host/sim/simulation.hpp"
#include "host_tests/support/alloc_counter.hpp"
#include "host_tests/support/temp_dir.hpp"

namespace {

std::uint64_t allocations_for(sinu::sim::SimMode mode, double duration_s) {
  sinu::test::TempDir dir;
  sinu::sim::SimOptions o;
  o.mode = mode;
  o.seed = 3;
  o.duration_s = duration_s;
  o.out_dir = dir.path().string();
  sinu::sim::SimResult r;
  sinu::dataset::Diagnostic err;
  sinu::test::AllocationScope scope;
  EXPECT_TRUE(sinu::sim::run_simulation(o, r, err)) << err.to_string();
  return scope.count();
}

}  // namespace

TEST(SimulateAlloc, AllocationsDoNotGrowWithTheSessionLength) {
  using sinu::sim::SimMode;
  EXPECT_EQ(allocations_for(SimMode::Flight, 400.0), allocations_for(SimMode::Flight, 800.0));
  EXPECT_EQ(allocations_for(SimMode::Static, 100.0), allocations_for(SimMode::Static, 1000.0));
}
