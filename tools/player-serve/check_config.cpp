#include "check_config.hpp"

#include <iomanip>
#include <ostream>

#include "config/config_file.hpp"
#include "config/errors.hpp"
#include "exit_status.hpp"

namespace playerkit::serve {
namespace {

void append_value(std::string& text, const config::Value& value) {
  if (value.is_string) text += '"';
  text += value.text;
  if (value.is_string) text += '"';
}

std::string format_property(const config::Property& property) {
  std::string text = property.name;
  text += property.is_tuple ? " [" : " ";
  for (std::size_t i = 0; i < property.values.size(); ++i) {
    if (i > 0) text += ' ';
    append_value(text, property.values[i]);
  }
  if (property.is_tuple) text += ']';
  return text;
}

}  // namespace

int check_config(const std::string& path, std::uint16_t default_port,
                 const std::function<bool(std::string_view)>& available, std::ostream& out,
                 std::ostream& err) {
  config::LoadOptions options;
  options.default_port = default_port;
  try {
    const auto config = config::ConfigFile::load(path, options);
    for (const auto& warning : config.warnings()) err << warning.to_string() << "\n";
    const auto& devices = config.devices();
    out << path << ": " << devices.size() << (devices.size() == 1 ? " device" : " devices");
    out << ", served on port";
    const auto ports = config.ports();
    if (ports.size() > 1) out << "s";
    for (std::size_t i = 0; i < ports.size(); ++i) out << (i ? ", " : " ") << ports[i];
    out << "\n";
    for (const auto& device : devices) {
      const std::string name = device.interface_name + ":" + std::to_string(device.address.index);
      out << "  " << std::left << std::setw(14) << name << " driver " << device.driver;
      if (available && !available(device.driver)) out << " (not in this build)";
      if (ports.size() > 1) out << ", port " << device.port;
      if (!device.robot_name.empty()) out << ", robot " << device.robot_name;
      if (device.alwayson) out << ", always on";
      out << "\n";
      for (const auto& property : config.section(device.section).properties()) {
        if (property.name == "driver" || property.name == "alwayson") continue;
        out << "      " << format_property(property) << "\n";
      }
    }
    return tools::kExitOk;
  } catch (const config::ConfigError& e) {
    err << e.what() << "\n";
    return tools::kExitUsage;
  }
}

}  // namespace playerkit::serve
