#pragma once
// A data message as the JSON object player-cat and player-log print: message_to_json, or
// message_to_si_json for --si. A payload that does not decode keeps its bytes
// as {"raw": [...]} so nothing is dropped; the first one per device is
// reported on `err`.
//
// Its own file, away from Boost.Asio: glibc's <signal.h> defines a macro
// `si_value`, which protocol/si_units.hpp uses as a parameter name.

#include <nlohmann/json.hpp>
#include <ostream>
#include <set>
#include <string>
#include <utility>

#include "protocol/device_address.hpp"
#include "protocol/message.hpp"

namespace playerkit::tools {

class MessageDecoder {
 public:
  // `program` prefixes the warnings ("player-cat: laser:0: data does not decode ...").
  MessageDecoder(std::string program, bool si, std::ostream& err)
      : program_(std::move(program)), si_(si), err_(err) {}

  nlohmann::json to_json(const protocol::Message& message);

 private:
  std::string program_;
  bool si_;
  std::ostream& err_;
  std::set<protocol::DeviceAddress> warned_;
};

}  // namespace playerkit::tools
