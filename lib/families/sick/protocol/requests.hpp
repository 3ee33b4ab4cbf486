#pragma once
// Every host request the sicklms200 and sickpls sheets list (T1-T8), as
// values: encode_request() gives the whole telegram, decode_request() reads a body
// (see unframe_request) back. The PLS uses T1 (with its own password), T2,
// T7 and T8; the LMS 200 all of them.
//
//   T1 InstallationModeRequest  20 00 + 8-byte password
//   T2 BaudRateRequest          20 42 (9600) / 41 (19200) / 40 (38400) / 48 (500000)
//   T3 GetTypeRequest           3A
//   T4 SetVariantRequest        3B width(LE, deg) resolution(LE, 0.01 deg)
//   T5 GetConfigRequest         74
//   T6 SetConfigRequest         77 + 34-byte configuration block
//   T7 StreamAllRequest         20 24
//   T8 StreamSubrangeRequest    20 27 first(LE) last(LE), 1-based, inclusive
//
// Anything else is an OtherRequest (the devices answer 0x92).

#include "families/sick/protocol/codes.hpp"
#include "families/sick/protocol/config_block.hpp"

#include <cstdint>
#include <span>
#include <string>
#include <variant>
#include <vector>

namespace playerkit::hardware::sick {

struct InstallationModeRequest {
  std::string password;  // 8 characters: installation_password(model)
  friend bool operator==(const InstallationModeRequest&, const InstallationModeRequest&) = default;
};

struct BaudRateRequest {
  int baud = 38400;  // one of kBaudRates
  friend bool operator==(const BaudRateRequest&, const BaudRateRequest&) = default;
};

struct GetTypeRequest {
  friend bool operator==(const GetTypeRequest&, const GetTypeRequest&) = default;
};

struct SetVariantRequest {
  Variant variant;
  friend bool operator==(const SetVariantRequest&, const SetVariantRequest&) = default;
};

struct GetConfigRequest {
  friend bool operator==(const GetConfigRequest&, const GetConfigRequest&) = default;
};

struct SetConfigRequest {
  ConfigBlock config;
  friend bool operator==(const SetConfigRequest&, const SetConfigRequest&) = default;
};

struct StreamAllRequest {
  friend bool operator==(const StreamAllRequest&, const StreamAllRequest&) = default;
};

// Value indices of a B7 scan: 1-based, both ends included.
struct Subrange {
  std::uint16_t first = 1;
  std::uint16_t last = 1;
  // last - first + 1, or 0 when last < first.
  [[nodiscard]] int count() const { return last < first ? 0 : last - first + 1; }
  friend bool operator==(const Subrange&, const Subrange&) = default;
};

struct StreamSubrangeRequest {
  Subrange range;
  friend bool operator==(const StreamSubrangeRequest&, const StreamSubrangeRequest&) = default;
};

// A command this library does not type (other 0x20 modes included).
struct OtherRequest {
  std::vector<std::uint8_t> body;  // command byte first
  friend bool operator==(const OtherRequest&, const OtherRequest&) = default;
};

using Request = std::variant<InstallationModeRequest, BaudRateRequest, GetTypeRequest,
                             SetVariantRequest, GetConfigRequest, SetConfigRequest,
                             StreamAllRequest, StreamSubrangeRequest, OtherRequest>;

// The body (command byte and parameters). Throws TelegramError for a value
// with no encoding: a password not 8 bytes long, a baud rate with no code,
// an empty OtherRequest.
std::vector<std::uint8_t> request_body(const Request& request);
// The whole telegram, 02 00 LEN body CRC.
std::vector<std::uint8_t> encode_request(const Request& request);

// Reads a body. A known command with the wrong length throws TelegramError
// ("SICK request 3B (set variant): expected 5 bytes, got 3"); an unknown one
// is an OtherRequest. Throws for an empty body. Never reads past the end.
Request decode_request(std::span<const std::uint8_t> body);

// "T1 installation mode": for logs and error messages.
std::string describe(const Request& request);

}  // namespace playerkit::hardware::sick
