#pragma once
// Moves the position of one GGA, RMC or GLL sentence by a NED offset in
// metres (GnssPositionJump in dataset_faults.hpp says exactly how).
#include <array>
#include <optional>
#include <string>
#include <string_view>

namespace sinu::test::faults {

/// The shifted sentence, or nullopt when the sentence is not a well-framed
/// GGA/RMC/GLL with a readable position (or the offset changes nothing).
std::optional<std::string> shift_position(std::string_view sentence, const std::array<double, 3>& offset_ned_m);

}  // namespace sinu::test::faults
