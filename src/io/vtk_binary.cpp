#include "io/vtk_binary.hpp"

#include <array>
#include <bit>
#include <cstdint>
#include <cstring>

#include "common/text.hpp"

namespace frontpack::detail {

namespace {

int base64_value(char c) {
  if (c >= 'A' && c <= 'Z') {
    return c - 'A';
  }
  if (c >= 'a' && c <= 'z') {
    return c - 'a' + 26;
  }
  if (c >= '0' && c <= '9') {
    return c - '0' + 52;
  }
  return c == '+' ? 62 : c == '/' ? 63 : -1;
}

// The unsigned integer of `size` bytes at `p`, in the file's byte order.
std::uint64_t read_unsigned(const char* p, std::size_t size, bool big_endian) {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < size; ++i) {
    const std::size_t k = big_endian ? i : size - 1 - i;
    v = (v << 8) | static_cast<unsigned char>(p[k]);
  }
  return v;
}

template <class T>
T from_bits(std::uint64_t bits) {
  if constexpr (sizeof(T) == 8) {
    return std::bit_cast<T>(bits);
  } else if constexpr (sizeof(T) == 4) {
    return std::bit_cast<T>(static_cast<std::uint32_t>(bits));
  } else if constexpr (sizeof(T) == 2) {
    return std::bit_cast<T>(static_cast<std::uint16_t>(bits));
  } else {
    return std::bit_cast<T>(static_cast<std::uint8_t>(bits));
  }
}

double value_of(VtkType type, std::uint64_t bits) {
  switch (type) {
    case VtkType::int8: return from_bits<std::int8_t>(bits);
    case VtkType::uint8: return from_bits<std::uint8_t>(bits);
    case VtkType::int16: return from_bits<std::int16_t>(bits);
    case VtkType::uint16: return from_bits<std::uint16_t>(bits);
    case VtkType::int32: return from_bits<std::int32_t>(bits);
    case VtkType::uint32: return from_bits<std::uint32_t>(bits);
    case VtkType::int64: return static_cast<double>(from_bits<std::int64_t>(bits));
    case VtkType::uint64: return static_cast<double>(bits);
    case VtkType::float32: return from_bits<float>(bits);
    case VtkType::float64: return from_bits<double>(bits);
  }
  return 0;
}

}  // namespace

std::optional<VtkType> vtk_type(std::string_view name) {
  constexpr std::array<std::pair<std::string_view, VtkType>, 10> names{{
      {"Int8", VtkType::int8},
      {"UInt8", VtkType::uint8},
      {"Int16", VtkType::int16},
      {"UInt16", VtkType::uint16},
      {"Int32", VtkType::int32},
      {"UInt32", VtkType::uint32},
      {"Int64", VtkType::int64},
      {"UInt64", VtkType::uint64},
      {"Float32", VtkType::float32},
      {"Float64", VtkType::float64},
  }};
  for (const auto& [n, t] : names) {
    if (n == name) {
      return t;
    }
  }
  return std::nullopt;
}

std::size_t vtk_size(VtkType type) {
  switch (type) {
    case VtkType::int8:
    case VtkType::uint8: return 1;
    case VtkType::int16:
    case VtkType::uint16: return 2;
    case VtkType::int32:
    case VtkType::uint32:
    case VtkType::float32: return 4;
    case VtkType::int64:
    case VtkType::uint64:
    case VtkType::float64: return 8;
  }
  return 8;
}

std::optional<std::string> decode_base64(std::string_view text, std::size_t& bad_at) {
  std::string out;
  out.reserve(text.size() / 4 * 3);
  std::array<int, 4> group{};
  std::size_t filled = 0;
  std::size_t padding = 0;
  std::size_t group_start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (is_c_space(c)) {
      continue;
    }
    if (filled == 0) {
      group_start = i;
    }
    const int v = c == '=' ? 0 : base64_value(c);
    // '=' only at the end of a group, after at least two characters.
    if (v < 0 || (c == '=' && filled < 2) || (c != '=' && padding > 0)) {
      bad_at = i;
      return std::nullopt;
    }
    padding += c == '=' ? 1 : 0;
    group[filled++] = v;
    if (filled == 4) {
      const std::uint32_t bits = (static_cast<std::uint32_t>(group[0]) << 18) |
                                 (static_cast<std::uint32_t>(group[1]) << 12) |
                                 (static_cast<std::uint32_t>(group[2]) << 6) | static_cast<std::uint32_t>(group[3]);
      out.push_back(static_cast<char>((bits >> 16) & 0xFF));
      if (padding < 2) {
        out.push_back(static_cast<char>((bits >> 8) & 0xFF));
      }
      if (padding < 1) {
        out.push_back(static_cast<char>(bits & 0xFF));
      }
      filled = 0;
      padding = 0;
    }
  }
  if (filled != 0) {
    bad_at = group_start;
    return std::nullopt;
  }
  return out;
}

std::string decode_block(std::string_view bytes, const BinaryLayout& layout, VtkType type, std::size_t count,
                         std::vector<double>& values) {
  const std::size_t header = layout.uint64_header ? 8 : 4;
  if (bytes.size() < header) {
    return "the binary data ends before its " + std::to_string(header) + "-byte header";
  }
  const std::uint64_t declared = read_unsigned(bytes.data(), header, layout.big_endian);
  const std::size_t size = vtk_size(type);
  if (declared != static_cast<std::uint64_t>(count) * size) {
    return "the binary header declares " + std::to_string(declared) + " bytes; " + std::to_string(count) +
           " values of " + std::to_string(size) + " bytes are " + std::to_string(count * size);
  }
  if (bytes.size() - header < count * size) {
    return "the binary data holds " + std::to_string(bytes.size() - header) + " bytes after its header, fewer than " +
           std::to_string(count * size);
  }
  values.clear();
  values.reserve(count);
  const char* p = bytes.data() + header;
  for (std::size_t i = 0; i < count; ++i, p += size) {
    values.push_back(value_of(type, read_unsigned(p, size, layout.big_endian)));
  }
  return {};
}

}  // namespace frontpack::detail
