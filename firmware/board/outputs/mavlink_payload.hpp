#pragma once
// A message payload being filled: fixed 255 bytes, zeroed, fields stored
// little-endian (MAVLink's wire byte order) at the slots of their message
// definition. The C++ type of each value must be the field's wire type.
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <type_traits>

#include "firmware/board/outputs/mavlink_message_def.hpp"

namespace sinu::board::mavlink {

inline constexpr std::size_t kMaxPayloadBytes = 255;

template <class T>
constexpr bool is_wire_type(WireType t) {
  switch (t) {
    case WireType::Uint8: return std::is_same_v<T, std::uint8_t>;
    case WireType::Int8: return std::is_same_v<T, std::int8_t>;
    case WireType::Char: return std::is_same_v<T, char>;
    case WireType::Uint16: return std::is_same_v<T, std::uint16_t>;
    case WireType::Int16: return std::is_same_v<T, std::int16_t>;
    case WireType::Uint32: return std::is_same_v<T, std::uint32_t>;
    case WireType::Int32: return std::is_same_v<T, std::int32_t>;
    case WireType::Float: return std::is_same_v<T, float>;
    case WireType::Uint64: return std::is_same_v<T, std::uint64_t>;
    case WireType::Int64: return std::is_same_v<T, std::int64_t>;
    case WireType::Double: return std::is_same_v<T, double>;
  }
  return false;
}

class Payload {
 public:
  /// Stores scalar field `F` (from mavlink::field(def, "name")).
  template <FieldSlot F, class T>
  void put(T value) {
    static_assert(F.count == 1, "an array field: use put_array");
    static_assert(is_wire_type<T>(F.type), "the value's type is not the field's wire type");
    store(F.offset, value);
  }

  /// Stores array field `F`, all its elements.
  template <FieldSlot F, class T, std::size_t K>
  void put_array(const std::array<T, K>& values) {
    static_assert(F.count == K, "the array length is not the field's");
    static_assert(is_wire_type<T>(F.type), "the element type is not the field's wire type");
    for (std::size_t i = 0; i < K; ++i) store(F.offset + i * sizeof(T), values[i]);
  }

  /// The first `length` bytes (the message's full payload length).
  std::span<const std::uint8_t> bytes(std::size_t length) const { return {bytes_.data(), length}; }

 private:
  template <class T>
  void store(std::size_t offset, T value) {
    using U = std::make_unsigned_t<std::conditional_t<std::is_floating_point_v<T>,
                                                      std::conditional_t<sizeof(T) == 4, std::int32_t, std::int64_t>, T>>;
    auto bits = std::bit_cast<U>(value);
    for (std::size_t i = 0; i < sizeof(T); ++i, bits = static_cast<U>(bits >> 8))
      bytes_[offset + i] = static_cast<std::uint8_t>(bits & 0xFFu);
  }

  std::array<std::uint8_t, kMaxPayloadBytes> bytes_{};
};

}  // namespace sinu::board::mavlink
