#include "firmware/host/sim/nmea_format.hpp"

#include <cmath>

namespace sinu::sim {

std::size_t format_utc(std::span<char> buf, double utc_s) {
  return board::format_time_of_day(buf, std::llround(utc_s * 100.0) % (86400LL * 100), 2);
}

std::size_t corrupt_sentence(std::span<char> buf, std::size_t len, Rng& rng) {
  std::size_t star = len;
  for (std::size_t i = 0; i < len; ++i)
    if (buf[i] == '*') star = i;
  switch (rng.below(3)) {
    case 0: {  // one character replaced: the checksum no longer matches
      const std::size_t i = 1 + rng.below(star - 1);
      char c = buf[i];
      while (c == buf[i] || c == '*' || c == '$' || c == ',') c = static_cast<char>('0' + rng.below(43));
      buf[i] = c;
      return len;
    }
    case 1: {  // cut before the '*': no checksum
      const std::size_t keep = 2 + rng.below(star - 2);
      buf[keep] = '\0';
      return keep;
    }
    default: {  // line noise: printable bytes, no '$'
      const std::size_t n = 10 + rng.below(30);
      for (std::size_t i = 0; i < n; ++i) buf[i] = static_cast<char>('%' + rng.below(90));
      buf[n] = '\0';
      return n;
    }
  }
}

}  // namespace sinu::sim
