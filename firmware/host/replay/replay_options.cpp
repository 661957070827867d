#include "firmware/host/replay/replay_options.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace sinu::replay {

namespace {
bool to_number(const std::string& s, double& v) {
  if (s.empty()) return false;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && std::isfinite(v);
}
}  // namespace

bool parse_outages(const std::string& text, std::vector<Outage>& out, std::string& error) {
  out.clear();
  if (text.empty()) return true;
  std::istringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    const std::size_t colon = item.find(':');
    Outage o;
    if (colon == std::string::npos || !to_number(item.substr(0, colon), o.start_s) ||
        !to_number(item.substr(colon + 1), o.duration_s) || !(o.duration_s > 0.0)) {
      error = "--outage: '" + item + "' is not START:DURATION with DURATION > 0 (seconds)";
      return false;
    }
    out.push_back(o);
  }
  return true;
}

}  // namespace sinu::replay
