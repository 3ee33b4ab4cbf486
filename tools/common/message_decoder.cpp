#include "message_decoder.hpp"

#include "protocol/errors.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message_json.hpp"
#include "protocol/si_units.hpp"

namespace playerkit::tools {

nlohmann::json MessageDecoder::to_json(const protocol::Message& message) {
  try {
    return si_ ? protocol::message_to_si_json(message) : protocol::message_to_json(message);
  } catch (const protocol::DecodeError& e) {
    if (warned_.insert(message.device()).second) {
      err_ << program_ << ": " << protocol::to_string(message.device()) << ": data does not decode ("
           << e.what() << "); printing its raw bytes\n";
    }
    nlohmann::json j;
    j["type"] = "data";
    j["device"] = protocol::interface_name(message.header.device);
    j["index"] = message.header.device_index;
    j["time"] = message.time().seconds();
    j["timestamp"] = message.timestamp().seconds();
    j["data"] = {{"raw", message.payload}};
    return j;
  }
}

}  // namespace playerkit::tools
