#pragma once
// Counts heap allocations made through global operator new in this test
// binary (alloc_counter.cpp replaces it). Use:
//   sinu::test::AllocationScope scope;  ...code...;  scope.count()
#include <atomic>
#include <cstdint>

namespace sinu::test {

std::uint64_t allocations_so_far();

class AllocationScope {
 public:
  AllocationScope() : start_(allocations_so_far()) {}
  std::uint64_t count() const { return allocations_so_far() - start_; }

 private:
  std::uint64_t start_;
};

}  // namespace sinu::test
