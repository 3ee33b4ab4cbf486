#pragma once
// Errors of the P2OS byte layer. Messages name the packet and the field,
// because whoever reads them is usually looking at a hex dump.

#include <stdexcept>

namespace playerkit::hardware::p2os {

// Bytes that are not the packet being decoded: truncated, wrong type byte,
// a count that does not match the length.
class DecodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A value that cannot be put into a packet (too long, out of range).
class EncodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace playerkit::hardware::p2os
