#include "check_config.hpp"

#include <iomanip>
#include <ostream>

#include "config/config_file.hpp"
#include "config/errors.hpp"
#include "core/plugin.hpp"
#include "daemon/check.hpp"
#include "sim/worldfile/worldfile_error.hpp"
#include "exit_status.hpp"
#include "text/printable.hpp"

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

void list_devices(const config::ConfigFile& config, std::ostream& out) {
  const auto& devices = config.devices();
  out << text::printable(config.filename()) << ": " << devices.size() << (devices.size() == 1 ? " device" : " devices");
  out << ", served on port";
  const auto ports = config.ports();
  if (ports.size() > 1) out << "s";
  for (std::size_t i = 0; i < ports.size(); ++i) out << (i ? ", " : " ") << ports[i];
  out << "\n";
  for (const auto& device : devices) {
    const std::string name = device.interface_name + ":" + std::to_string(device.address.index);
    out << "  " << std::left << std::setw(14) << name << " driver " << device.driver;
    if (ports.size() > 1) out << ", port " << device.port;
    if (!device.robot_name.empty()) out << ", robot " << device.robot_name;
    if (device.alwayson) out << ", always on";
    out << "\n";
    for (const auto& property : config.section(device.section).properties()) {
      if (property.name == "driver" || property.name == "alwayson") continue;
      out << "      " << text::printable(format_property(property)) << "\n";
    }
  }
}

}  // namespace

int check_config(const daemon::ServeOptions& options, std::ostream& out, std::ostream& err) {
  try {
    const auto checked = daemon::check_configuration(options);
    for (const auto& warning : checked.warnings) err << warning << "\n";
    for (const auto& config : checked.configs) list_devices(config, out);
    return tools::kExitOk;
  } catch (const config::ConfigError& e) {
    err << e.what() << "\n";
    return tools::kExitUsage;
  } catch (const sim::worldfile::WorldFileError& e) {
    err << e.what() << "\n";  // file:line:col, escaped already
    return tools::kExitUsage;
  } catch (const core::PluginError& e) {
    err << options.program_name << ": " << text::printable(e.what()) << "\n";
    return tools::kExitFailure;
  } catch (const std::runtime_error& e) {  // the -r log, a world that cannot be served
    err << options.program_name << ": " << text::printable(e.what()) << "\n";
    return tools::kExitUsage;
  }
}

}  // namespace playerkit::serve
