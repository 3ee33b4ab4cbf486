#pragma once
// The device's answers to requests (sicklms200.md §2.2, sickpls.md §2), as
// values: encode_reply() gives the whole telegram (02 80 LEN code data status
// CRC), parse_*() reads an unframed Reply (unframe_reply) and throws
// TelegramError for a wrong code or length, never reading past the end.
// Scans (B0/B7) are in scan.hpp.
//
//   A0 result                 switch mode (T1, T2, T7, T8): 00 ok, 01 wrong password, 02 fault
//   BA text                   type (T3), e.g. "LMS200;30106" padded to 20
//   BB accepted w(LE) r(LE)   set variant (T4): 01 accepted / 00 refused, the active variant
//   F4 block(34)              configuration (T5)
//   F7 accepted block(34)     set configuration (T6): 01 / 00, the resulting block
//   92 00                     not acknowledged: unknown or refused command

#include "families/sick/protocol/codes.hpp"
#include "families/sick/protocol/config_block.hpp"
#include "families/sick/protocol/telegram.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace playerkit::hardware::sick {

enum class ModeResult : std::uint8_t { ok = 0x00, wrong_password = 0x01, fault = 0x02 };

struct ModeReply {
  ModeResult result = ModeResult::ok;
  friend bool operator==(const ModeReply&, const ModeReply&) = default;
};

struct TypeReply {
  std::string type;  // as sent, padding included
  // The text without trailing spaces and NULs.
  [[nodiscard]] std::string trimmed() const;
  friend bool operator==(const TypeReply&, const TypeReply&) = default;
};

struct VariantReply {
  bool accepted = true;
  Variant variant;  // the variant now active
  friend bool operator==(const VariantReply&, const VariantReply&) = default;
};

struct ConfigReply {
  ConfigBlock config;
  friend bool operator==(const ConfigReply&, const ConfigReply&) = default;
};

struct SetConfigReply {
  bool accepted = true;
  ConfigBlock config;  // the configuration now active
  friend bool operator==(const SetConfigReply&, const SetConfigReply&) = default;
};

struct NotAcknowledgedReply {
  std::uint8_t detail = 0x00;
  friend bool operator==(const NotAcknowledgedReply&, const NotAcknowledgedReply&) = default;
};

std::vector<std::uint8_t> encode_reply(const ModeReply& reply, std::uint8_t status = kStatusOk);
// Throws TelegramError for a text too long for a telegram.
std::vector<std::uint8_t> encode_reply(const TypeReply& reply, std::uint8_t status = kStatusOk);
std::vector<std::uint8_t> encode_reply(const VariantReply& reply, std::uint8_t status = kStatusOk);
std::vector<std::uint8_t> encode_reply(const ConfigReply& reply, std::uint8_t status = kStatusOk);
std::vector<std::uint8_t> encode_reply(const SetConfigReply& reply,
                                       std::uint8_t status = kStatusOk);
std::vector<std::uint8_t> encode_reply(const NotAcknowledgedReply& reply,
                                       std::uint8_t status = kStatusOk);

// Each checks the code and the data length. The Player drivers accept any
// A0 result and F7 acceptance byte; these report them and let callers decide.
ModeReply parse_mode_reply(const Reply& reply);
TypeReply parse_type_reply(const Reply& reply);
VariantReply parse_variant_reply(const Reply& reply);
ConfigReply parse_config_reply(const Reply& reply);
SetConfigReply parse_set_config_reply(const Reply& reply);
NotAcknowledgedReply parse_not_acknowledged(const Reply& reply);

}  // namespace playerkit::hardware::sick
