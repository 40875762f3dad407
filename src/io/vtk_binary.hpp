// The binary encodings of VTK XML files: base64 text and the block layout of a binary array (a
// byte-count header of UInt32 or UInt64, then the values), without compression.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frontpack::detail {

/// The scalar types of a VTK DataArray.
enum class VtkType { int8, uint8, int16, uint16, int32, uint32, int64, uint64, float32, float64 };

/// The type named `name` ("Float64", "Int32", ...), or none.
[[nodiscard]] std::optional<VtkType> vtk_type(std::string_view name);
/// Bytes per value.
[[nodiscard]] std::size_t vtk_size(VtkType type);

/// The bytes of base64 `text`. Whitespace is skipped; each group of 4 characters is decoded on
/// its own, so that pieces encoded separately (VTK encodes a header and its data one after the
/// other, each padded with '=') decode to their concatenation. Returns none for a character
/// outside the base64 alphabet or a group cut short, and sets `bad_at` to its offset in `text`.
[[nodiscard]] std::optional<std::string> decode_base64(std::string_view text, std::size_t& bad_at);

/// How a binary array is laid out.
struct BinaryLayout {
  bool uint64_header = false;  ///< header_type="UInt64" (else UInt32)
  bool big_endian = false;     ///< byte_order="BigEndian"
};

/// The `count` values of type `type` of the binary block at the start of `bytes` (a byte-count
/// header, then the data), as doubles (exact for the floating-point types and for integers up to
/// 2^53). Returns an error message, empty on success.
[[nodiscard]] std::string decode_block(std::string_view bytes, const BinaryLayout& layout, VtkType type,
                                       std::size_t count, std::vector<double>& values);

}  // namespace frontpack::detail
