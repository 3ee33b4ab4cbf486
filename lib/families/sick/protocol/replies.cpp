#include "families/sick/protocol/replies.hpp"

#include "families/sick/protocol/byte_fields.hpp"

#include <algorithm>
#include <cstdio>

namespace playerkit::hardware::sick {
using detail::byte_hex;
using detail::append_le16;
using detail::load_le16;
namespace {

void expect_code(const Reply& reply, std::uint8_t code, const char* what) {
  if (reply.code != code) {
    throw TelegramError("SICK " + byte_hex(code) + " reply (" + what + "): got reply code " +
                        byte_hex(reply.code));
  }
}

void expect_data(const Reply& reply, std::size_t size, const char* what) {
  if (reply.data.size() != size) {
    throw TelegramError("SICK " + byte_hex(reply.code) + " reply (" + what + "): " +
                        (reply.data.size() < size ? "truncated: " : "too long: ") + "expected " +
                        std::to_string(size) + " data bytes, got " +
                        std::to_string(reply.data.size()));
  }
}

bool acceptance(std::uint8_t byte) { return byte != 0; }

}  // namespace

std::string TypeReply::trimmed() const {
  const auto end = type.find_last_not_of(std::string_view(" \0", 2));
  return end == std::string::npos ? std::string() : type.substr(0, end + 1);
}

std::vector<std::uint8_t> encode_reply(const ModeReply& reply, std::uint8_t status) {
  const std::uint8_t data[] = {static_cast<std::uint8_t>(reply.result)};
  return frame_reply(kSwitchModeReply, data, status);
}

std::vector<std::uint8_t> encode_reply(const TypeReply& reply, std::uint8_t status) {
  const std::vector<std::uint8_t> data(reply.type.begin(), reply.type.end());
  return frame_reply(kTypeReply, data, status);
}

std::vector<std::uint8_t> encode_reply(const VariantReply& reply, std::uint8_t status) {
  std::vector<std::uint8_t> data = {static_cast<std::uint8_t>(reply.accepted ? 0x01 : 0x00)};
  append_le16(data, reply.variant.width_deg);
  append_le16(data, reply.variant.resolution_cdeg);
  return frame_reply(kVariantReply, data, status);
}

std::vector<std::uint8_t> encode_reply(const ConfigReply& reply, std::uint8_t status) {
  return frame_reply(kConfigReply, reply.config.bytes, status);
}

std::vector<std::uint8_t> encode_reply(const SetConfigReply& reply, std::uint8_t status) {
  std::vector<std::uint8_t> data = {static_cast<std::uint8_t>(reply.accepted ? 0x01 : 0x00)};
  data.insert(data.end(), reply.config.bytes.begin(), reply.config.bytes.end());
  return frame_reply(kSetConfigReply, data, status);
}

std::vector<std::uint8_t> encode_reply(const NotAcknowledgedReply& reply, std::uint8_t status) {
  const std::uint8_t data[] = {reply.detail};
  return frame_reply(kNotAcknowledged, data, status);
}

ModeReply parse_mode_reply(const Reply& reply) {
  expect_code(reply, kSwitchModeReply, "switch mode");
  expect_data(reply, 1, "switch mode");
  return {static_cast<ModeResult>(reply.data[0])};
}

TypeReply parse_type_reply(const Reply& reply) {
  expect_code(reply, kTypeReply, "type");
  return {std::string(reply.data.begin(), reply.data.end())};
}

VariantReply parse_variant_reply(const Reply& reply) {
  expect_code(reply, kVariantReply, "set variant");
  expect_data(reply, 5, "set variant");
  return {acceptance(reply.data[0]), {load_le16(reply.data, 1), load_le16(reply.data, 3)}};
}

ConfigReply parse_config_reply(const Reply& reply) {
  expect_code(reply, kConfigReply, "configuration");
  expect_data(reply, kConfigBlockSize, "configuration");
  ConfigReply parsed;
  std::copy(reply.data.begin(), reply.data.end(), parsed.config.bytes.begin());
  return parsed;
}

SetConfigReply parse_set_config_reply(const Reply& reply) {
  expect_code(reply, kSetConfigReply, "set configuration");
  expect_data(reply, 1 + kConfigBlockSize, "set configuration");
  SetConfigReply parsed;
  parsed.accepted = acceptance(reply.data[0]);
  std::copy(reply.data.begin() + 1, reply.data.end(), parsed.config.bytes.begin());
  return parsed;
}

NotAcknowledgedReply parse_not_acknowledged(const Reply& reply) {
  expect_code(reply, kNotAcknowledged, "not acknowledged");
  // The detail byte is what the sheet shows; a bare 92 is still a refusal.
  return {reply.data.empty() ? std::uint8_t{0} : reply.data[0]};
}

}  // namespace playerkit::hardware::sick
