#pragma once

namespace frontpack {
inline constexpr int version_major = 0;
inline constexpr int version_minor = 4;
inline constexpr int version_patch = 0;
inline constexpr const char* version_string = "0.4.0";
}  // namespace frontpack
