#include "json_line.hpp"

#include <algorithm>
#include <array>
#include <string>

#include <nlohmann/json.hpp>

#include "outgoing_message.hpp"
#include "protocol/errors.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message_json.hpp"
#include "usage_error.hpp"

namespace playerkit::player_send {

namespace {

constexpr std::array<std::string_view, 7> kKeys{"type", "device", "index", "time", "timestamp", "request", "data"};

void check_keys(const nlohmann::json& j) {
  for (const auto& item : j.items()) {
    if (std::find(kKeys.begin(), kKeys.end(), item.key()) == kKeys.end()) {
      throw UsageError("unknown key '" + item.key() +
                       "' (allowed: type, device, index, request, data; time and timestamp are ignored)");
    }
  }
}

// "position:0" in "device" becomes the full form's "device":"position","index":0.
void split_device(nlohmann::json& j) {
  if (const auto index = j.find("index");
      index != j.end() && !(index->is_number_unsigned() && index->get<std::uint64_t>() <= 0xFFFF)) {
    throw UsageError("\"index\" must be a number 0..65535, got " + index->dump());
  }
  const auto it = j.find("device");
  if (it == j.end()) throw UsageError("\"device\" is missing (like \"device\":\"position:0\")");
  if (!it->is_string()) return;  // a numeric code: message_from_json checks it
  const auto text = it->get<std::string>();
  const auto device = parse_device(text);
  if (text.find(':') != std::string::npos) {
    if (j.contains("index") && j["index"] != device.index) {
      throw UsageError("\"device\":\"" + text + "\" and \"index\":" + j["index"].dump() + " disagree");
    }
    j["index"] = device.index;
  }
  if (protocol::find_interface(device.interface)) {
    *it = protocol::interface_name(device.interface);
  } else {
    *it = device.interface;  // a code 1.5 does not define: only {"raw":[...]} data can go there
  }
}

void default_type(nlohmann::json& j) {
  if (!j.contains("type")) {
    j["type"] = j.contains("request") ? "req" : "cmd";
    return;
  }
  const auto& type = j["type"];
  if (type == "cmd" && j.contains("request")) {
    throw UsageError("a \"cmd\" line names a \"request\": drop one of them");
  }
  if (type != "cmd" && type != "req") {
    throw UsageError("\"type\":" + type.dump() +
                     " cannot be sent: only \"cmd\" and \"req\" lines (turn data into commands first, e.g. with jq)");
  }
}

}  // namespace

protocol::Message message_from_line(std::string_view line) {
  auto j = nlohmann::json::parse(line, nullptr, /*allow_exceptions=*/false);
  if (j.is_discarded()) throw UsageError("not valid JSON");
  if (!j.is_object()) throw UsageError("expected a JSON object, got " + j.dump());
  check_keys(j);
  split_device(j);
  default_type(j);
  j.erase("time");
  j.erase("timestamp");
  try {
    return protocol::message_from_json(j);
  } catch (const protocol::JsonError& e) {
    throw UsageError(e.what());
  } catch (const protocol::EncodeError& e) {
    throw UsageError(e.what());
  } catch (const nlohmann::json::exception& e) {
    // A key of the wrong JSON type ("index":"zero", "request":5).
    throw UsageError(std::string("bad value: ") + e.what());
  }
}

}  // namespace playerkit::player_send
