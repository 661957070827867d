#pragma once
// Exit codes of every sinu subcommand.
namespace sinu::cli {
inline constexpr int kExitOk = 0;       // success
inline constexpr int kExitFailure = 1;  // runtime failure, message on stderr
inline constexpr int kExitUsage = 2;    // usage error, or a mode that has not landed yet
}  // namespace sinu::cli
