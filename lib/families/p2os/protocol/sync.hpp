#pragma once
// The handshake's packets (p2os.md §2.2, §2.4). SYNC0 and SYNC1 are echoed
// as bare type bytes; SYNC2's reply names the robot, and its class and
// subclass select the parameter row (robot_params.hpp).

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace playerkit::hardware::p2os {

// The reference copies each string into a 20-byte buffer.
inline constexpr std::size_t kMaxSyncStringLength = 19;

struct Sync2Reply {
  std::string name;
  std::string robot_class;  // "Pioneer"
  std::string subclass;     // "p3dx", a row of robot_params.hpp

  friend bool operator==(const Sync2Reply&, const Sync2Reply&) = default;
};

// `02 name\0 class\0 subclass\0`. Throws EncodeError when a string is longer
// than kMaxSyncStringLength or contains a NUL.
std::vector<std::uint8_t> encode_sync2_reply(const Sync2Reply& reply);
// Throws DecodeError when the type is not 2 or a string lacks its NUL.
// Longer strings are returned whole (the reference would overflow).
Sync2Reply decode_sync2_reply(std::span<const std::uint8_t> payload);

}  // namespace playerkit::hardware::p2os
