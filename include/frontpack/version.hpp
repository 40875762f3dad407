#pragma once

namespace frontpack {
inline constexpr int version_major = 0;
inline constexpr int version_minor = 3;
inline constexpr int version_patch = 0;
inline constexpr const char* version_string = "0.3.0";
}  // namespace frontpack
