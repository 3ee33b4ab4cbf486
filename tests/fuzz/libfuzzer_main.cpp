// The libFuzzer entry of one target: CMake compiles this file once per
// target with PLAYERKIT_FUZZ_TARGET set to the target's function name.

#include <cstddef>
#include <cstdint>

#include "fuzz_targets.hpp"

#ifndef PLAYERKIT_FUZZ_TARGET
#error "PLAYERKIT_FUZZ_TARGET names the target function"
#endif

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return playerkit::fuzz::PLAYERKIT_FUZZ_TARGET(data, size);
}
