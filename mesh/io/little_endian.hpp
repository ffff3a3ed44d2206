#pragma once
// Byte-order-explicit loads and stores for the binary formats (.tsm, VTU
// appended data), independent of the host's byte order.
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace tetsmooth {

template <class T>
using le_uint_t =
    std::conditional_t<sizeof(T) == 1, std::uint8_t,
                       std::conditional_t<sizeof(T) == 2, std::uint16_t,
                                          std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;

// Stores an arithmetic value as sizeof(T) bytes, least significant first.
template <class T>
inline void store_le(unsigned char* p, T value) {
  static_assert(std::is_arithmetic_v<T> && sizeof(T) <= 8);
  le_uint_t<T> bits;
  std::memcpy(&bits, &value, sizeof bits);
  for (std::size_t i = 0; i < sizeof(T); ++i) p[i] = static_cast<unsigned char>(bits >> (8 * i));
}

// Loads sizeof(T) bytes, least significant first (big_endian: most
// significant first).
template <class T>
inline T load_le(const unsigned char* p, bool big_endian = false) {
  static_assert(std::is_arithmetic_v<T> && sizeof(T) <= 8);
  le_uint_t<T> bits = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i) {
    const std::size_t byte = big_endian ? sizeof(T) - 1 - i : i;
    bits = static_cast<le_uint_t<T>>(bits | static_cast<le_uint_t<T>>(static_cast<le_uint_t<T>>(p[byte]) << (8 * i)));
  }
  T value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

}  // namespace tetsmooth
