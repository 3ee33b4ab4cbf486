#include "run_plan.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>

#include "driver_lookup.hpp"
#include "drivers_exit_status.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::player_drivers {

namespace {

bool is_number(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return false;
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc{} && end == text.data() + text.size() && std::isfinite(value);
}

bool documents(const core::DriverSpec& spec, std::string_view option) {
  const std::vector<core::OptionDoc> rows = spec.doc.option_rows();
  return std::any_of(rows.begin(), rows.end(), [option](const core::OptionDoc& doc) {
    // "laser_max_beams/laser_max_samples": any of the names.
    std::string_view names = doc.name;
    while (!names.empty()) {
      const std::size_t slash = names.find('/');
      if (names.substr(0, slash) == option) return true;
      if (slash == std::string_view::npos) break;
      names.remove_prefix(slash + 1);
    }
    return false;
  });
}

std::string device_text(protocol::DeviceAddress address) { return protocol::to_string(address); }

}  // namespace

OptionAssignment parse_option_assignment(std::string_view word) {
  const std::size_t equals = word.find('=');
  if (equals == std::string_view::npos) {
    throw UsageError("'" + std::string(word) + "' is not OPTION=VALUE (e.g. port=/dev/ttyUSB0)");
  }
  const std::string_view name = word.substr(0, equals);
  const bool name_ok = !name.empty() && !std::isdigit(static_cast<unsigned char>(name.front())) &&
                       std::all_of(name.begin(), name.end(), [](char c) {
                         return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
                       });
  if (!name_ok) {
    throw UsageError("'" + std::string(word) + "': '" + std::string(name) +
                     "' is not an option name (letters, digits and '_')");
  }
  return {std::string(name), std::string(word.substr(equals + 1))};
}

std::string config_value(std::string_view value) {
  if (value.find_first_of("\r\n") != std::string_view::npos) {
    throw UsageError("a value cannot span lines: '" + std::string(value) + "'");
  }
  if (is_number(value)) return std::string(value.front() == '+' ? value.substr(1) : value);
  const bool quoted = value.size() >= 2 && value.front() == '"' && value.back() == '"';
  if (quoted && value.substr(1, value.size() - 2).find('"') == std::string_view::npos) return std::string(value);
  if (value.size() >= 2 && value.front() == '[' && value.back() == ']') return std::string(value);
  if (value.find('"') != std::string_view::npos) {
    throw UsageError("'" + std::string(value) + "': a configuration string cannot hold '\"'");
  }
  return "\"" + std::string(value) + "\"";
}

std::vector<protocol::DeviceAddress> family_addresses(const std::vector<const core::DriverSpec*>& drivers) {
  std::map<std::uint16_t, std::uint16_t> next_index;
  std::vector<protocol::DeviceAddress> addresses;
  for (const auto* spec : drivers) {
    const std::uint16_t interface = spec->interfaces.empty() ? protocol::kNullCode : spec->interfaces.front();
    addresses.push_back({interface, next_index[interface]++});
  }
  return addresses;
}

RunPlan make_run_plan(const core::DriverRegistry& registry, const PlanRequest& request) {
  const DriverSelection selection = select_drivers(registry, request.name);
  RunPlan plan;
  plan.name = request.name;
  plan.family = selection.family;

  auto addresses = family_addresses(selection.drivers);
  if (request.serve_as) {
    if (selection.family) {
      throw UsageError("--device " + device_text(*request.serve_as) + ": " + request.name +
                       " is a family; its devices are numbered for you (player-drivers info " + request.name + ")");
    }
    const auto& served = selection.drivers.front()->interfaces;
    if (std::find(served.begin(), served.end(), request.serve_as->interface) == served.end()) {
      std::string names;
      for (std::size_t i = 0; i < served.size() && i < 8; ++i) names += (i ? ", " : "") + protocol::interface_name(served[i]);
      if (served.size() > 8) names += ", ...";
      throw UsageError("--device " + device_text(*request.serve_as) + ": " + request.name + " serves " + names);
    }
    addresses.front() = *request.serve_as;
  }
  for (std::size_t i = 0; i < selection.drivers.size(); ++i) {
    plan.devices.push_back({addresses[i], selection.drivers[i], {}});
  }

  for (std::size_t i = 0; i < request.options.size(); ++i) {
    const OptionAssignment& option = request.options[i];
    for (std::size_t j = 0; j < i; ++j) {
      if (request.options[j].name == option.name) {
        throw UsageError("option '" + option.name + "' is given twice (" + request.options[j].name + "=" +
                         request.options[j].value + ", " + option.name + "=" + option.value + ")");
      }
    }
    config_value(option.value);  // refuse what cannot be written before anything starts
    auto owner = std::find_if(plan.devices.begin(), plan.devices.end(),
                              [&](const PlannedDevice& device) { return documents(*device.spec, option.name); });
    if (owner == plan.devices.end()) owner = plan.devices.begin();
    owner->options.push_back(option);
  }

  std::string text = "# player-drivers run " + request.name + "\n";
  int line = 2;
  for (const PlannedDevice& device : plan.devices) {
    plan.line_sources[line] = device.spec->name + " (" + device_text(device.address) + ")";
    text += device_text(device.address) + " ( driver \"" + device.spec->name + "\"\n";
    ++line;
    for (const OptionAssignment& option : device.options) {
      plan.line_sources[line] = "option " + option.name + "=" + option.value;
      plan.option_lines[line] = option;
      text += "  " + option.name + " " + config_value(option.value) + "\n";
      ++line;
    }
    text += ")\n";
    ++line;
  }

  if (request.record_file) {
    std::string devices;
    for (const PlannedDevice& device : plan.devices) {
      const auto access = device.spec->access;
      if (access == protocol::Access::kRead || access == protocol::Access::kAll) {
        devices += (devices.empty() ? "\"" : " \"") + device_text(device.address) + "\"";
      }
    }
    if (devices.empty()) {
      throw UsageError("--record: " + request.name + " has no device to read from, so nothing to record");
    }
    std::uint16_t index = 0;
    for (const PlannedDevice& device : plan.devices) {
      if (device.address.interface == protocol::kNullCode) index = std::max<std::uint16_t>(index, device.address.index + 1);
    }
    plan.recorder = protocol::DeviceAddress{protocol::kNullCode, index};
    const std::string file = std::filesystem::absolute(*request.record_file).lexically_normal().string();
    plan.line_sources[line] = "--record " + *request.record_file;
    text += device_text(*plan.recorder) + " ( driver \"writelog\" filename " + config_value(file) + " devices [" +
            devices + "] alwayson 1 )\n";
  }
  plan.config_text = std::move(text);
  return plan;
}

std::optional<ConfigMessage> split_config_message(std::string_view config_name, std::string_view message) {
  const std::string prefix = std::string(config_name) + ":";
  if (!message.starts_with(prefix)) return std::nullopt;
  std::string_view rest = message.substr(prefix.size());
  int line = 0;
  const auto [after_line, error] = std::from_chars(rest.data(), rest.data() + rest.size(), line);
  if (error != std::errc{}) return std::nullopt;
  rest = rest.substr(static_cast<std::size_t>(after_line - rest.data()));
  if (rest.starts_with(": ")) return ConfigMessage{line, std::string(rest.substr(2))};
  // ":col: message"
  const std::size_t end = rest.find(": ");
  if (!rest.starts_with(":") || end == std::string_view::npos) return std::nullopt;
  return ConfigMessage{line, std::string(rest.substr(end + 2))};
}

std::string explain_config_message(const RunPlan& plan, std::string_view config_name, std::string_view message) {
  const auto located = split_config_message(config_name, message);
  if (!located) return std::string(message);
  const auto source = plan.line_sources.find(located->line);
  if (source == plan.line_sources.end()) return std::string(message);
  return source->second + ": " + located->text;
}

}  // namespace playerkit::player_drivers
