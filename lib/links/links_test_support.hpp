#pragma once
// Shared by the links tests: temporary directories and bounded reads.

#include <gtest/gtest.h>
#include <stdlib.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "links/byte_link.hpp"
#include "links/pseudo_terminal.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::links::test_support {

using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

// Generous: only reached when something is broken.
inline constexpr auto kPatience = 5s;

using TemporaryDirectory = ::playerkit::testing::ScratchDirectory;

// Reads until `count` bytes arrived or kPatience passed.
inline Bytes read_exactly(ByteLink& link, std::size_t count) {
  Bytes received;
  const Deadline deadline = deadline_in(kPatience);
  std::vector<std::uint8_t> chunk(count);
  while (received.size() < count) {
    const std::size_t got = link.read_some(std::span(chunk).first(count - received.size()), deadline);
    if (got == 0) break;
    received.insert(received.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(got));
  }
  return received;
}

inline Bytes read_exactly(PseudoTerminal& pty, std::size_t count) {
  Bytes received;
  const Deadline deadline = deadline_in(kPatience);
  std::vector<std::uint8_t> chunk(count);
  while (received.size() < count && LinkClock::now() < deadline) {
    const auto got = pty.read_some(std::span(chunk).first(count - received.size()), deadline);
    received.insert(received.end(), chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(got.count));
  }
  return received;
}

}  // namespace playerkit::links::test_support
