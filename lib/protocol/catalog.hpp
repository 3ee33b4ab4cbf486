#pragma once
// Which struct each message of each interface carries: the data packet, the
// command, and every configuration request by subtype, with the struct of its
// reply. Tools use it to turn any payload into JSON and back, and to offer
// requests by readable name ("get-geom", "set-odom").

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "protocol/binary_codec.hpp"
#include "protocol/json_codec.hpp"
#include "protocol/layout.hpp"

namespace playerkit::protocol {

// A wire struct behind a type-erased interface.
struct PayloadCodec {
  std::string_view wire_name;
  std::size_t min_size = 0;
  std::size_t max_size = 0;
  nlohmann::json (*to_json)(std::span<const std::uint8_t> payload);  // throws DecodeError
  std::vector<std::uint8_t> (*from_json)(const nlohmann::json& j);   // throws JsonError, EncodeError
};

template <WireStruct T>
const PayloadCodec& codec_of() {
  static const PayloadCodec codec{
      T::kWireName,
      kMinWireSize<T>,
      kMaxWireSize<T>,
      [](std::span<const std::uint8_t> payload) { return to_json(decode<T>(payload)); },
      [](const nlohmann::json& j) { return encode(from_json<T>(j)); },
  };
  return codec;
}

enum class RequestForm {
  kStruct,  // the request carries the struct (set-odom, set-config)
  kQuery,   // the request is only the subtype; the reply carries the struct (get-geom)
};

struct RequestKind {
  std::string_view name;  // "get-geom"
  std::uint16_t subtype = 0;
  RequestForm form = RequestForm::kStruct;
  const PayloadCodec* request = nullptr;  // struct of a kStruct request
  const PayloadCodec* reply = nullptr;    // payload of the ACK; nullptr: empty
  std::string_view summary;               // one line for --help
};

struct InterfaceMessages {
  std::uint16_t interface = 0;
  std::size_t subtype_size = 1;  // 2 for the `player` device, 1 for all others
  const PayloadCodec* data = nullptr;
  const PayloadCodec* command = nullptr;
  std::span<const RequestKind> requests;

  [[nodiscard]] const RequestKind* find_request(std::string_view name) const;
  [[nodiscard]] const RequestKind* find_request(std::uint16_t subtype) const;
};

// The messages of one interface code; nullptr for codes Player 1.5 does not define.
const InterfaceMessages* find_messages(std::uint16_t interface);
std::span<const InterfaceMessages> all_messages();

}  // namespace playerkit::protocol
