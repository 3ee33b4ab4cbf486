#include "families/sick/protocol/telegram.hpp"

#include "families/sick/protocol/byte_fields.hpp"

#include "families/sick/protocol/crc.hpp"

#include <cstdio>

namespace playerkit::hardware::sick {
using detail::append_le16;
using detail::load_le16;
namespace {

std::vector<std::uint8_t> frame(std::uint8_t address, std::span<const std::uint8_t> body_start,
                                std::span<const std::uint8_t> body_rest = {},
                                std::span<const std::uint8_t> body_end = {}) {
  const std::size_t length = body_start.size() + body_rest.size() + body_end.size();
  std::vector<std::uint8_t> out;
  out.reserve(kHeaderSize + length + kCrcSize);
  out.push_back(kStx);
  out.push_back(address);
  append_le16(out, static_cast<std::uint16_t>(length));
  out.insert(out.end(), body_start.begin(), body_start.end());
  out.insert(out.end(), body_rest.begin(), body_rest.end());
  out.insert(out.end(), body_end.begin(), body_end.end());
  append_le16(out, crc16(out));
  return out;
}

// Checks everything but the body's meaning and returns the body.
std::span<const std::uint8_t> checked_body(std::span<const std::uint8_t> telegram,
                                           std::uint8_t address, const char* what) {
  const auto fail = [&](const std::string& problem) {
    return TelegramError(std::string("SICK ") + what + " telegram " + hex(telegram) + ": " +
                         problem);
  };
  if (telegram.size() < kHeaderSize + kCrcSize) {
    throw fail("truncated: " + std::to_string(telegram.size()) + " bytes, a telegram has at least " +
               std::to_string(kHeaderSize + kCrcSize));
  }
  if (telegram[0] != kStx) throw fail("does not start with STX 02");
  if (telegram[1] != address) {
    char expected[8];
    std::snprintf(expected, sizeof expected, "%02X", address);
    throw fail(std::string("address is not ") + expected);
  }
  const std::size_t length = load_le16(telegram, 2);
  if (telegram.size() != kHeaderSize + length + kCrcSize) {
    throw fail("LEN " + std::to_string(length) + " says " +
               std::to_string(kHeaderSize + length + kCrcSize) + " bytes, got " +
               std::to_string(telegram.size()));
  }
  const std::size_t covered = kHeaderSize + length;
  const std::uint16_t sent = load_le16(telegram, covered);
  const std::uint16_t computed = crc16(telegram.first(covered));
  if (sent != computed) {
    char numbers[48];
    std::snprintf(numbers, sizeof numbers, "CRC %04X, computed %04X", sent, computed);
    throw fail(numbers);
  }
  return telegram.subspan(kHeaderSize, length);
}

}  // namespace

std::vector<std::uint8_t> frame_request(std::span<const std::uint8_t> body) {
  if (body.empty()) throw TelegramError("SICK request: empty body (a command byte is needed)");
  if (body.size() > kMaxBodyLength) {
    throw TelegramError("SICK request: body of " + std::to_string(body.size()) +
                        " bytes exceeds " + std::to_string(kMaxBodyLength));
  }
  return frame(kRequestAddress, body);
}

std::vector<std::uint8_t> frame_reply(std::uint8_t code, std::span<const std::uint8_t> data,
                                      std::uint8_t status) {
  if (data.size() + 2 > kMaxBodyLength) {
    throw TelegramError("SICK reply: " + std::to_string(data.size()) +
                        " data bytes exceed the longest body, " + std::to_string(kMaxBodyLength));
  }
  return frame(kReplyAddress, std::span(&code, 1), data, std::span(&status, 1));
}

std::vector<std::uint8_t> frame_reply(const Reply& reply) {
  return frame_reply(reply.code, reply.data, reply.status);
}

std::vector<std::uint8_t> unframe_request(std::span<const std::uint8_t> telegram) {
  const auto body = checked_body(telegram, kRequestAddress, "request");
  if (body.empty()) throw TelegramError("SICK request telegram " + hex(telegram) + ": LEN 0");
  return {body.begin(), body.end()};
}

Reply unframe_reply(std::span<const std::uint8_t> telegram) {
  const auto body = checked_body(telegram, kReplyAddress, "reply");
  if (body.size() < 2) {
    throw TelegramError("SICK reply telegram " + hex(telegram) + ": LEN " +
                        std::to_string(body.size()) + ", a reply has a code and a status byte");
  }
  return Reply{body.front(), {body.begin() + 1, body.end() - 1}, body.back()};
}

std::string hex(std::span<const std::uint8_t> bytes, std::size_t max_bytes) {
  std::string out;
  const std::size_t shown = bytes.size() < max_bytes ? bytes.size() : max_bytes;
  for (std::size_t i = 0; i < shown; ++i) {
    char digits[4];
    std::snprintf(digits, sizeof digits, "%02X", bytes[i]);
    if (i > 0) out += ' ';
    out += digits;
  }
  if (shown < bytes.size()) out += " ... (" + std::to_string(bytes.size()) + " bytes)";
  return out;
}

}  // namespace playerkit::hardware::sick
