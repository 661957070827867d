#pragma once
// A MAVLink message definition as the XML gives it (fields in declaration
// order, extensions marked), and its wire layout derived at compile time by
// the rules of mavlink.io "Packet Serialization":
//  - base fields sorted by the size of their type, largest first, stable
//    (arrays by their element type);
//  - extension fields after them, in XML order;
//  - CRC_EXTRA: CRC-16/MCRF4XX over "NAME " and, for each base field in wire
//    order, "type name " (and the array length as one byte), folded to 8 bits.
// The encoders write fields by name; a misspelt name or a value of the wrong
// C++ type does not compile.
#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "firmware/board/outputs/mavlink_crc.hpp"

namespace sinu::board::mavlink {

enum class WireType : std::uint8_t { Uint8, Int8, Char, Uint16, Int16, Uint32, Int32, Float, Uint64, Int64, Double };

constexpr std::size_t wire_size(WireType t) {
  switch (t) {
    case WireType::Uint8: case WireType::Int8: case WireType::Char: return 1;
    case WireType::Uint16: case WireType::Int16: return 2;
    case WireType::Uint32: case WireType::Int32: case WireType::Float: return 4;
    case WireType::Uint64: case WireType::Int64: case WireType::Double: return 8;
  }
  return 0;
}

/// The type as the XML spells it (what CRC_EXTRA hashes). The HEARTBEAT's
/// magic `uint8_t_mavlink_version` is hashed as "uint8_t", as the generator does.
constexpr std::string_view wire_type_name(WireType t) {
  switch (t) {
    case WireType::Uint8: return "uint8_t";
    case WireType::Int8: return "int8_t";
    case WireType::Char: return "char";
    case WireType::Uint16: return "uint16_t";
    case WireType::Int16: return "int16_t";
    case WireType::Uint32: return "uint32_t";
    case WireType::Int32: return "int32_t";
    case WireType::Float: return "float";
    case WireType::Uint64: return "uint64_t";
    case WireType::Int64: return "int64_t";
    case WireType::Double: return "double";
  }
  return "";
}

struct FieldDef {
  WireType type;
  std::string_view name;
  std::uint8_t array_length = 0;  // 0: a scalar; N: type[N]
  bool extension = false;         // declared after <extensions/>
};

template <std::size_t N>
struct MessageDef {
  std::string_view name;
  std::uint32_t id;
  std::array<FieldDef, N> fields;  // XML declaration order
};

/// What framing needs to know of a message.
struct MessageInfo {
  std::uint32_t id = 0;
  std::uint8_t length = 0;       // full payload, extensions included (MAVLINK_MSG_ID_x_LEN)
  std::uint8_t base_length = 0;  // without the extensions (MAVLINK_MSG_ID_x_MIN_LEN)
  std::uint8_t crc_extra = 0;    // MAVLINK_MSG_ID_x_CRC
};

/// Where one field lives in the payload (a template argument of the writer).
struct FieldSlot {
  WireType type;
  std::uint8_t offset;  // bytes from the payload start
  std::uint8_t count;   // elements (1 for a scalar)
};

namespace detail {

constexpr std::size_t element_count(const FieldDef& f) { return f.array_length == 0 ? 1 : f.array_length; }

/// Field indices (into `fields`) in wire order.
template <std::size_t N>
constexpr std::array<std::size_t, N> wire_order(const MessageDef<N>& def) {
  std::array<std::size_t, N> order{};
  std::size_t k = 0;
  for (const std::size_t size : {8u, 4u, 2u, 1u})  // one pass per size: a stable sort
    for (std::size_t i = 0; i < N; ++i)
      if (!def.fields[i].extension && wire_size(def.fields[i].type) == size) order[k++] = i;
  for (std::size_t i = 0; i < N; ++i)
    if (def.fields[i].extension) order[k++] = i;
  if (k != N) throw "a field has no wire size";
  return order;
}

/// Payload offset of every field, by XML index.
template <std::size_t N>
constexpr std::array<std::size_t, N> offsets(const MessageDef<N>& def) {
  std::array<std::size_t, N> at{};
  std::size_t offset = 0;
  for (const std::size_t i : wire_order(def)) {
    at[i] = offset;
    offset += wire_size(def.fields[i].type) * element_count(def.fields[i]);
  }
  return at;
}

template <std::size_t N>
constexpr std::size_t payload_bytes(const MessageDef<N>& def, bool with_extensions) {
  std::size_t bytes = 0;
  for (const FieldDef& f : def.fields)
    if (with_extensions || !f.extension) bytes += wire_size(f.type) * element_count(f);
  return bytes;
}

template <std::size_t N>
constexpr std::uint8_t crc_extra(const MessageDef<N>& def) {
  std::uint16_t crc = crc_accumulate(def.name, kCrcSeed);
  crc = crc_accumulate(' ', crc);
  for (const std::size_t i : wire_order(def)) {
    const FieldDef& f = def.fields[i];
    if (f.extension) continue;
    crc = crc_accumulate(wire_type_name(f.type), crc);
    crc = crc_accumulate(' ', crc);
    crc = crc_accumulate(f.name, crc);
    crc = crc_accumulate(' ', crc);
    if (f.array_length != 0) crc = crc_accumulate(f.array_length, crc);
  }
  return static_cast<std::uint8_t>((crc & 0xFF) ^ (crc >> 8));
}

}  // namespace detail

template <std::size_t N>
consteval MessageInfo message_info(const MessageDef<N>& def) {
  const std::size_t length = detail::payload_bytes(def, true);
  if (length > 255) throw "a MAVLink payload holds at most 255 bytes";
  return {def.id, static_cast<std::uint8_t>(length), static_cast<std::uint8_t>(detail::payload_bytes(def, false)),
          detail::crc_extra(def)};
}

/// The slot of field `name`; a name the definition does not have does not compile.
template <std::size_t N>
consteval FieldSlot field(const MessageDef<N>& def, std::string_view name) {
  const auto at = detail::offsets(def);
  for (std::size_t i = 0; i < N; ++i)
    if (def.fields[i].name == name)
      return {def.fields[i].type, static_cast<std::uint8_t>(at[i]),
              static_cast<std::uint8_t>(detail::element_count(def.fields[i]))};
  throw "no field of that name in the message definition";
}

}  // namespace sinu::board::mavlink
