#include "families/p2os/protocol/sync.hpp"

#include "families/p2os/protocol/byte_cursor.hpp"
#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/packet_types.hpp"

#include <algorithm>
#include <string_view>

namespace playerkit::hardware::p2os {
namespace {

constexpr std::string_view kSyncName = "P2OS SYNC2 reply";

void append_string(std::vector<std::uint8_t>& out, const std::string& text,
                   std::string_view field) {
  if (text.size() > kMaxSyncStringLength || text.find('\0') != std::string::npos) {
    throw EncodeError(std::string(kSyncName) + ": " + std::string(field) + " \"" + text +
                      "\" must be at most 19 characters without NUL");
  }
  out.insert(out.end(), text.begin(), text.end());
  out.push_back(0);
}

std::string read_string(detail::ByteCursor& in, std::string_view field) {
  const auto rest = in.rest();
  const auto nul = std::find(rest.begin(), rest.end(), std::uint8_t{0});
  if (nul == rest.end()) {
    throw DecodeError(std::string(kSyncName) + ": " + std::string(field) +
                      " has no terminating NUL (truncated)");
  }
  std::string text(rest.begin(), nul);
  // Give back what follows the NUL.
  const auto used = static_cast<std::size_t>(nul - rest.begin()) + 1;
  in = detail::ByteCursor(rest.subspan(used), kSyncName);
  return text;
}

}  // namespace

std::vector<std::uint8_t> encode_sync2_reply(const Sync2Reply& reply) {
  std::vector<std::uint8_t> out{packet_type::sync2};
  append_string(out, reply.name, "name");
  append_string(out, reply.robot_class, "class");
  append_string(out, reply.subclass, "subclass");
  return out;
}

Sync2Reply decode_sync2_reply(std::span<const std::uint8_t> payload) {
  detail::ByteCursor in(payload, kSyncName);
  detail::expect_type(in, packet_type::sync2, kSyncName);
  Sync2Reply reply;
  reply.name = read_string(in, "name");
  reply.robot_class = read_string(in, "class");
  reply.subclass = read_string(in, "subclass");
  return reply;
}

}  // namespace playerkit::hardware::p2os
