// Cancellation: every long loop of the library polls a std::stop_token and throws CancelledError
// once a stop is requested, so that a cancelled run ends within milliseconds at any stage.
#pragma once

#include <cstddef>
#include <stop_token>

#include "frontpack/errors.hpp"

namespace frontpack::detail {

inline void throw_if_stopped(const std::stop_token& stop) {
  if (stop.stop_requested()) {
    throw CancelledError();
  }
}

/// Polls every 4096 iterations (an atomic load each time would cost as much as the loop body of
/// a writer); `i` is the loop's index.
inline void throw_if_stopped(const std::stop_token& stop, std::size_t i) {
  if ((i & 4095) == 0) {
    throw_if_stopped(stop);
  }
}

}  // namespace frontpack::detail
