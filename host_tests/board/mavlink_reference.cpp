#include "host_tests/board/mavlink_reference.hpp"

#include <algorithm>
#include <cstring>
#include <stdexcept>

namespace sinu::test::mavref {

namespace {

// Field tables transcribed from message_definitions/v1.0 (github:mavlink/mavlink).
const XmlMessage kHeartbeat{"HEARTBEAT", 0, {
    {"uint8_t", "type"}, {"uint8_t", "autopilot"}, {"uint8_t", "base_mode"}, {"uint32_t", "custom_mode"},
    {"uint8_t", "system_status"}, {"uint8_t_mavlink_version", "mavlink_version"}}};

const XmlMessage kGpsInput{"GPS_INPUT", 232, {
    {"uint64_t", "time_usec"}, {"uint8_t", "gps_id"}, {"uint16_t", "ignore_flags"}, {"uint32_t", "time_week_ms"},
    {"uint16_t", "time_week"}, {"uint8_t", "fix_type"}, {"int32_t", "lat"}, {"int32_t", "lon"}, {"float", "alt"},
    {"float", "hdop"}, {"float", "vdop"}, {"float", "vn"}, {"float", "ve"}, {"float", "vd"},
    {"float", "speed_accuracy"}, {"float", "horiz_accuracy"}, {"float", "vert_accuracy"},
    {"uint8_t", "satellites_visible"},
    {"uint16_t", "yaw", true}}};

const XmlMessage kOdometry{"ODOMETRY", 331, {
    {"uint64_t", "time_usec"}, {"uint8_t", "frame_id"}, {"uint8_t", "child_frame_id"}, {"float", "x"},
    {"float", "y"}, {"float", "z"}, {"float[4]", "q"}, {"float", "vx"}, {"float", "vy"}, {"float", "vz"},
    {"float", "rollspeed"}, {"float", "pitchspeed"}, {"float", "yawspeed"}, {"float[21]", "pose_covariance"},
    {"float[21]", "velocity_covariance"},
    {"uint8_t", "reset_counter", true}, {"uint8_t", "estimator_type", true}, {"int8_t", "quality", true}}};

struct ParsedType {
  std::string element;
  unsigned array_length;
  unsigned bytes;
};

ParsedType parse_type(const std::string& xml_type) {
  std::string element = xml_type;
  unsigned n = 0;
  if (const auto open = xml_type.find('['); open != std::string::npos) {
    element = xml_type.substr(0, open);
    n = static_cast<unsigned>(std::stoul(xml_type.substr(open + 1)));
  }
  if (element == "uint8_t_mavlink_version") element = "uint8_t";  // the generator's rewrite
  static const std::map<std::string, unsigned> sizes = {
      {"char", 1},    {"uint8_t", 1},  {"int8_t", 1},  {"uint16_t", 2}, {"int16_t", 2}, {"uint32_t", 4},
      {"int32_t", 4}, {"float", 4},    {"uint64_t", 8}, {"int64_t", 8}, {"double", 8}};
  return {element, n, sizes.at(element)};
}

std::uint64_t read_le(const std::uint8_t* p, unsigned bytes) {
  std::uint64_t v = 0;
  for (unsigned i = bytes; i-- > 0;) v = (v << 8) | p[i];
  return v;
}

double decode_element(const std::uint8_t* p, const WireField& f) {
  const std::uint64_t u = read_le(p, f.element_bytes);
  const std::string& t = f.element_type;
  if (t == "float") {
    float x;
    const auto bits = static_cast<std::uint32_t>(u);
    std::memcpy(&x, &bits, 4);
    return x;
  }
  if (t == "double") {
    double x;
    std::memcpy(&x, &u, 8);
    return x;
  }
  if (t == "int8_t") return static_cast<std::int8_t>(u);
  if (t == "int16_t") return static_cast<std::int16_t>(u);
  if (t == "int32_t") return static_cast<std::int32_t>(u);
  if (t == "int64_t") return static_cast<double>(static_cast<std::int64_t>(u));
  return static_cast<double>(u);
}

}  // namespace

const XmlMessage& heartbeat_xml() { return kHeartbeat; }
const XmlMessage& gps_input_xml() { return kGpsInput; }
const XmlMessage& odometry_xml() { return kOdometry; }

const XmlMessage* message_by_id(std::uint32_t id) {
  for (const XmlMessage* m : {&kHeartbeat, &kGpsInput, &kOdometry})
    if (m->id == id) return m;
  return nullptr;
}

std::vector<WireField> wire_layout(const XmlMessage& m) {
  std::vector<WireField> base, extensions;
  for (const XmlField& x : m.fields) {
    const ParsedType t = parse_type(x.type);
    (x.extension ? extensions : base).push_back({x.name, t.element, t.array_length, t.bytes, 0, x.extension});
  }
  std::stable_sort(base.begin(), base.end(),
                   [](const WireField& a, const WireField& b) { return a.element_bytes > b.element_bytes; });
  base.insert(base.end(), extensions.begin(), extensions.end());
  unsigned offset = 0;
  for (WireField& f : base) {
    f.offset = offset;
    offset += f.element_bytes * std::max(f.array_length, 1u);
  }
  return base;
}

unsigned payload_length(const XmlMessage& m, bool with_extensions) {
  unsigned n = 0;
  for (const WireField& f : wire_layout(m))
    if (with_extensions || !f.extension) n += f.element_bytes * std::max(f.array_length, 1u);
  return n;
}

std::uint8_t generator_crc_extra(const XmlMessage& m) {
  std::vector<std::uint8_t> text;
  auto add = [&text](const std::string& s) { text.insert(text.end(), s.begin(), s.end()); };
  add(m.name + " ");
  for (const WireField& f : wire_layout(m)) {
    if (f.extension) continue;  // extensions are not part of CRC_EXTRA
    add(f.element_type + " ");
    add(f.name + " ");
    if (f.array_length != 0) text.push_back(static_cast<std::uint8_t>(f.array_length));
  }
  const std::uint16_t crc = crc_mcrf4xx(text);
  return static_cast<std::uint8_t>((crc & 0xFF) ^ (crc >> 8));
}

std::uint16_t crc_mcrf4xx(std::span<const std::uint8_t> bytes, std::uint16_t crc) {
  for (const std::uint8_t b : bytes) {
    crc = static_cast<std::uint16_t>(crc ^ b);
    for (int bit = 0; bit < 8; ++bit)
      crc = static_cast<std::uint16_t>((crc & 1u) != 0 ? (crc >> 1) ^ 0x8408u : crc >> 1);
  }
  return crc;
}

ParseResult parse(std::span<const std::uint8_t> bytes) {
  ParseResult r;
  std::size_t i = 0;
  while (i < bytes.size()) {
    if (bytes[i] != 0xFD) {
      ++r.noise_bytes;
      ++i;
      continue;
    }
    if (bytes.size() - i < 12) {
      r.incomplete_bytes += static_cast<unsigned>(bytes.size() - i);
      break;
    }
    const unsigned len = bytes[i + 1];
    const bool signed_frame = (bytes[i + 2] & 0x01) != 0;
    const std::size_t total = 12 + len + (signed_frame ? 13 : 0);
    if (bytes.size() - i < total) {
      r.incomplete_bytes += static_cast<unsigned>(bytes.size() - i);
      break;
    }
    Frame f;
    f.len = len;
    f.incompat = bytes[i + 2];
    f.compat = bytes[i + 3];
    f.seq = bytes[i + 4];
    f.sysid = bytes[i + 5];
    f.compid = bytes[i + 6];
    f.msgid = static_cast<std::uint32_t>(read_le(&bytes[i + 7], 3));
    const XmlMessage* m = message_by_id(f.msgid);
    if (m == nullptr) {
      ++r.unknown_id;
      ++i;
      continue;
    }
    std::vector<std::uint8_t> crc_input(bytes.begin() + static_cast<std::ptrdiff_t>(i + 1),
                                        bytes.begin() + static_cast<std::ptrdiff_t>(i + 10 + len));
    crc_input.push_back(generator_crc_extra(*m));
    const auto sent_crc = static_cast<std::uint16_t>(read_le(&bytes[i + 10 + len], 2));
    if (crc_mcrf4xx(crc_input) != sent_crc) {
      ++r.bad_crc;
      ++i;
      continue;
    }
    f.raw.assign(bytes.begin() + static_cast<std::ptrdiff_t>(i), bytes.begin() + static_cast<std::ptrdiff_t>(i + total));
    f.payload.assign(bytes.begin() + static_cast<std::ptrdiff_t>(i + 10),
                     bytes.begin() + static_cast<std::ptrdiff_t>(i + 10 + len));
    f.payload.resize(std::max<std::size_t>(len, payload_length(*m, true)), 0);  // un-truncate
    for (const WireField& w : wire_layout(*m)) {
      std::vector<double>& v = f.values[w.name];
      for (unsigned k = 0; k < std::max(w.array_length, 1u); ++k)
        v.push_back(decode_element(&f.payload[w.offset + k * w.element_bytes], w));
    }
    r.frames.push_back(std::move(f));
    i += total;
  }
  return r;
}

}  // namespace sinu::test::mavref
