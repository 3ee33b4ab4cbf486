#include "families/sick/protocol/requests.hpp"

#include "families/sick/protocol/byte_fields.hpp"

#include "families/sick/protocol/telegram.hpp"

#include <cstdio>

namespace playerkit::hardware::sick {
using detail::append_le16;
using detail::load_le16;
using detail::byte_hex;
namespace {

template <class... Visitors>
struct Overloaded : Visitors... {
  using Visitors::operator()...;
};
template <class... Visitors>
Overloaded(Visitors...) -> Overloaded<Visitors...>;

// Throws unless `body` is exactly `size` bytes long.
void expect_size(std::span<const std::uint8_t> body, std::size_t size, const char* what) {
  if (body.size() != size) {
    std::string command = byte_hex(body[0]);
    if (body[0] == kSwitchModeCommand && body.size() > 1) command += " " + byte_hex(body[1]);
    throw TelegramError("SICK request " + command + " (" + what + "): expected " +
                        std::to_string(size) + " bytes, got " + std::to_string(body.size()));
  }
}

Request decode_switch_mode(std::span<const std::uint8_t> body) {
  if (body.size() < 2) {
    throw TelegramError("SICK request 20 (switch mode): expected a mode byte, got 1 byte");
  }
  const std::uint8_t mode = body[1];
  if (mode == kInstallationMode) {
    expect_size(body, 2 + kPasswordLength, "installation mode");
    return InstallationModeRequest{std::string(body.begin() + 2, body.end())};
  }
  if (mode == kStreamAllMode) {
    expect_size(body, 2, "stream all values");
    return StreamAllRequest{};
  }
  if (mode == kStreamSubrangeMode) {
    expect_size(body, 6, "stream a subrange");
    return StreamSubrangeRequest{{load_le16(body, 2), load_le16(body, 4)}};
  }
  if (const auto baud = baud_of_code(mode)) {
    expect_size(body, 2, "baud rate");
    return BaudRateRequest{*baud};
  }
  return OtherRequest{{body.begin(), body.end()}};
}

}  // namespace

std::vector<std::uint8_t> request_body(const Request& request) {
  return std::visit(
      Overloaded{
          [](const InstallationModeRequest& r) {
            if (r.password.size() != kPasswordLength) {
              throw TelegramError("SICK installation mode request: the password must be " +
                                  std::to_string(kPasswordLength) + " bytes, got " +
                                  std::to_string(r.password.size()));
            }
            std::vector<std::uint8_t> body = {kSwitchModeCommand, kInstallationMode};
            body.insert(body.end(), r.password.begin(), r.password.end());
            return body;
          },
          [](const BaudRateRequest& r) {
            const auto code = baud_code(r.baud);
            if (!code) {
              throw TelegramError("SICK baud rate request: no code for " + std::to_string(r.baud) +
                                  " baud (9600, 19200, 38400, 500000)");
            }
            return std::vector<std::uint8_t>{kSwitchModeCommand, *code};
          },
          [](const GetTypeRequest&) { return std::vector<std::uint8_t>{kGetTypeCommand}; },
          [](const SetVariantRequest& r) {
            std::vector<std::uint8_t> body = {kSetVariantCommand};
            append_le16(body, r.variant.width_deg);
            append_le16(body, r.variant.resolution_cdeg);
            return body;
          },
          [](const GetConfigRequest&) { return std::vector<std::uint8_t>{kGetConfigCommand}; },
          [](const SetConfigRequest& r) {
            std::vector<std::uint8_t> body = {kSetConfigCommand};
            body.insert(body.end(), r.config.bytes.begin(), r.config.bytes.end());
            return body;
          },
          [](const StreamAllRequest&) {
            return std::vector<std::uint8_t>{kSwitchModeCommand, kStreamAllMode};
          },
          [](const StreamSubrangeRequest& r) {
            std::vector<std::uint8_t> body = {kSwitchModeCommand, kStreamSubrangeMode};
            append_le16(body, r.range.first);
            append_le16(body, r.range.last);
            return body;
          },
          [](const OtherRequest& r) {
            if (r.body.empty()) throw TelegramError("SICK request: empty body");
            return r.body;
          },
      },
      request);
}

std::vector<std::uint8_t> encode_request(const Request& request) {
  return frame_request(request_body(request));
}

Request decode_request(std::span<const std::uint8_t> body) {
  if (body.empty()) throw TelegramError("SICK request: empty body (no command byte)");
  switch (body[0]) {
    case kSwitchModeCommand: return decode_switch_mode(body);
    case kGetTypeCommand: expect_size(body, 1, "get type"); return GetTypeRequest{};
    case kGetConfigCommand: expect_size(body, 1, "get configuration"); return GetConfigRequest{};
    case kSetVariantCommand:
      expect_size(body, 5, "set variant");
      return SetVariantRequest{{load_le16(body, 1), load_le16(body, 3)}};
    case kSetConfigCommand: {
      expect_size(body, 1 + kConfigBlockSize, "set configuration");
      SetConfigRequest request;
      std::copy(body.begin() + 1, body.end(), request.config.bytes.begin());
      return request;
    }
    default: return OtherRequest{{body.begin(), body.end()}};
  }
}

std::string describe(const Request& request) {
  return std::visit(
      Overloaded{
          [](const InstallationModeRequest&) { return std::string("T1 installation mode"); },
          [](const BaudRateRequest& r) { return "T2 baud rate " + std::to_string(r.baud); },
          [](const GetTypeRequest&) { return std::string("T3 get type"); },
          [](const SetVariantRequest& r) {
            return "T4 set variant " + std::to_string(r.variant.width_deg) + " deg / " +
                   std::to_string(r.variant.resolution_cdeg) + " cdeg";
          },
          [](const GetConfigRequest&) { return std::string("T5 get configuration"); },
          [](const SetConfigRequest&) { return std::string("T6 set configuration"); },
          [](const StreamAllRequest&) { return std::string("T7 stream all values"); },
          [](const StreamSubrangeRequest& r) {
            return "T8 stream values " + std::to_string(r.range.first) + ".." +
                   std::to_string(r.range.last);
          },
          [](const OtherRequest& r) {
            return "command " + (r.body.empty() ? std::string("(none)") : hex(r.body, 4));
          },
      },
      request);
}

}  // namespace playerkit::hardware::sick
