#pragma once
// Hex dumps of link traffic for `--trace`:
//
//   tcp:127.0.0.1:4001    0.012345 > 02 00 02 00 20 40 50 08
//   tcp:127.0.0.1:4001    0.031002 < 06 02 80 03 00 A0 00 10 16 0A
//
// ">" is host -> device, "<" is device -> host; the time is seconds since
// the hook was made.

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>

#include "links/byte_link.hpp"

namespace playerkit::links {

// "02 80 03 00"; upper-case, one space between bytes.
std::string hex_bytes(std::span<const std::uint8_t> bytes);

std::string format_trace_line(std::string_view label, Direction direction, std::span<const std::uint8_t> bytes,
                              LinkClock::duration since_start);

// A hook that hands one formatted line (no newline) per read or write to
// `sink`, never two at once.
TraceHook hex_trace_hook(std::string label, std::function<void(std::string_view line)> sink);

}  // namespace playerkit::links
