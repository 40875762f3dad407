// libFuzzer entry point: one program per target, chosen at compile time (FRONTPACK_FUZZ_TARGET).
#include <cstddef>
#include <cstdint>

#include "fuzz_targets.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  frontpack::fuzz::FRONTPACK_FUZZ_TARGET(data, size);
  return 0;
}
