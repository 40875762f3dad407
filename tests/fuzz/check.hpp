// check(): the fuzz targets' assertion. A broken guarantee prints what broke and aborts, which
// libFuzzer (and the sanitizers) report as a crash with the input that caused it.
#pragma once

#include <cstdio>
#include <cstdlib>

namespace frontpack::fuzz {

inline void check(bool ok, const char* what) {
  if (!ok) {
    std::fprintf(stderr, "frontpack fuzz: guarantee broken: %s\n", what);
    std::abort();
  }
}

}  // namespace frontpack::fuzz
