// check(): the fuzz targets' assertion. A broken guarantee prints what broke and aborts, which
// libFuzzer (and the sanitizers) report as a crash with the input that caused it.
#pragma once

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "frontpack/domain.hpp"

namespace frontpack::fuzz {

inline void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "frontpack fuzz: guarantee broken: %s\n", what);
    std::abort();
  }
}

/// What a reader's error message must be, whatever the input: a line of printable text (the
/// user's text quoted escaped, a NUL byte as \0) of bounded length (the user's text cut to 40
/// characters), so that it can be printed to a terminal or a log as it is.
inline void check_message(const std::string& message) {
  bool printable = true;
  for (const char c : message) {
    const auto u = static_cast<unsigned char>(c);
    printable = printable && u >= 0x20 && u != 0x7f;
  }
  check(printable, "an error message carries no control character (the user's text is escaped)");
  check(message.size() <= 512, "an error message quotes at most 40 characters of the user's text");
}

/// What a domain any reader accepted must be: of positive finite area, in a finite box that is
/// not degenerate.
inline void check_accepted_domain(const Domain& domain) {
  const double area = domain.area();
  check(std::isfinite(area) && area > 0, "an accepted domain has a positive finite area");
  const Box b = domain.bbox();
  check(std::isfinite(b.xmin) && std::isfinite(b.xmax) && std::isfinite(b.ymin) && std::isfinite(b.ymax) &&
            b.xmin < b.xmax && b.ymin < b.ymax,
        "an accepted domain has a finite, non-degenerate box");
}

}  // namespace frontpack::fuzz
