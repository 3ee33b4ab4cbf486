#include <cstdio>
#include <cstdlib>

#include "fuzz_targets.hpp"

namespace playerkit::fuzz {

void invariant_failed(const char* target, const char* what) {
  std::fprintf(stderr, "fuzz target %s: invariant broken: %s\n", target, what);
  std::abort();
}

}  // namespace playerkit::fuzz
