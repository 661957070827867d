#pragma once
// Locates ../shared/ data; tests that need it skip with a message where it is
// absent (a user's clone has no ../shared/).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace sinu::test {

inline std::filesystem::path shared_dir() {
  if (const char* env = std::getenv("SINU_SHARED_DIR")) return env;
  return SINU_SHARED_DIR;
}

/// Path under ../shared/, or "" if it does not exist.
inline std::string shared_path(const std::string& rel) {
  const auto p = shared_dir() / rel;
  return std::filesystem::exists(p) ? p.string() : std::string{};
}

}  // namespace sinu::test

/// Skips the current test when ../shared/<rel> is absent; else binds `var`.
#define SINU_REQUIRE_SHARED(var, rel)                                                                  \
  const std::string var = ::sinu::test::shared_path(rel);                                              \
  if (var.empty()) GTEST_SKIP() << "../shared/" << (rel) << " is absent (set SINU_SHARED_DIR): skipped"
