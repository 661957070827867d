#include "drivers/imu/axis_map.hpp"

namespace sinu::drivers {

std::optional<AxisMap> AxisMap::parse(std::string_view text) {
  AxisMap m;
  std::array<bool, 3> used{};
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t comma = text.find(',');
    std::string_view item = text.substr(0, comma);
    m.sign[i] = 1.0;
    if (!item.empty() && (item.front() == '-' || item.front() == '+')) {
      if (item.front() == '-') m.sign[i] = -1.0;
      item.remove_prefix(1);
    }
    if (item.size() != 1 || item[0] < 'x' || item[0] > 'z') return std::nullopt;
    const int a = item[0] - 'x';
    if (used[static_cast<std::size_t>(a)]) return std::nullopt;
    used[static_cast<std::size_t>(a)] = true;
    m.axis[i] = a;
    if ((i < 2) != (comma != std::string_view::npos)) return std::nullopt;
    if (comma != std::string_view::npos) text.remove_prefix(comma + 1);
  }
  return m;
}

}  // namespace sinu::drivers
