#pragma once
// One key of a configuration schema, as a schema reader was asked for it.
#include <string>

namespace sinu::board {

struct ConfigKey {
  std::string path;         // "outputs.mavlink.udp_port"
  bool has_default = true;  // false: optional, or required only when a feature is on
};

}  // namespace sinu::board
