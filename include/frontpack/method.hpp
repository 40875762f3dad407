// The methods a fill runs (FillOptions::method): the shared vocabulary of the generators, the
// orchestration, the tool and Python, kept apart from fill.hpp so that a stage that only needs to
// know which method runs includes this and nothing of the fill's options or results.
// Standard library only.
#pragma once

#include <cstdint>

namespace frontpack {

enum class Method : std::uint8_t {
  closed,  ///< Sec. 2: grows from three mutually tangent disks at the centre
  open,    ///< Sec. 3: layer by layer from the bottom wall, walls as disks of infinite radius
  /// Beyond the paper: the domain's own edges are the walls (the open form's walls generalised
  /// to every edge of every ring, reflex vertices as zero-radius obstacles); the front starts
  /// along all rings and advances inwards, and voids behind it take later, smaller disks.
  /// Nothing is culled; the density next to the boundary is that of the interior.
  boundary,
};

/// The method's name as the tool and Python spell it ("closed", "open", "boundary").
[[nodiscard]] constexpr const char* to_string(Method method) noexcept {
  switch (method) {
    case Method::closed: return "closed";
    case Method::open: return "open";
    case Method::boundary: return "boundary";
  }
  return "unknown";
}

}  // namespace frontpack
