#include "driver_listing.hpp"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>
#include <vector>

#include "driver_lookup.hpp"
#include "protocol/interfaces.hpp"
#include "run_plan.hpp"

namespace playerkit::player_drivers {

namespace {

constexpr std::size_t kInterfacesShown = 3;

bool serves_every_interface(const core::DriverSpec& spec) {
  return spec.interfaces.size() >= protocol::all_interfaces().size();
}

std::vector<std::string> interface_names(const core::DriverSpec& spec) {
  std::vector<std::string> names;
  for (const auto code : spec.interfaces) names.push_back(protocol::interface_name(code));
  return names;
}

// "laser", "power,position,sonar,+11", "any".
std::string short_interfaces(const core::DriverSpec& spec) {
  if (serves_every_interface(spec)) return "any";
  const auto names = interface_names(spec);
  std::string text;
  for (std::size_t i = 0; i < names.size() && i < kInterfacesShown; ++i) text += (i ? "," : "") + names[i];
  if (names.size() > kInterfacesShown) text += ",+" + std::to_string(names.size() - kInterfacesShown);
  return text;
}

std::string access_letter(protocol::Access access) { return std::string(1, static_cast<char>(access)); }

nlohmann::json options_json(const core::DriverSpec& spec) {
  nlohmann::json options = nlohmann::json::array();
  for (const auto& option : spec.doc.option_rows()) {
    options.push_back({{"name", option.name},
                       {"type", option.type},
                       {"default", option.default_value},
                       {"unit", option.unit},
                       {"summary", option.summary}});
  }
  return options;
}

nlohmann::json list_json(const core::DriverSpec& spec) {
  return {{"name", spec.name},
          {"interfaces", interface_names(spec)},
          {"access", access_letter(spec.access)},
          {"needs_hardware", spec.doc.needs_hardware},
          {"family", spec.family},
          {"documented", !spec.doc.manual_section.empty() || !spec.doc.option_rows().empty()},
          {"summary", spec.summary}};
}

std::string padded(const std::string& text, std::size_t width) {
  return text + std::string(width > text.size() ? width - text.size() : 0, ' ');
}

void write_options_table(const core::DriverSpec& spec, std::ostream& out) {
  const std::vector<core::OptionDoc> rows = spec.doc.option_rows();
  if (rows.empty()) {
    out << "Options: not documented for this driver";
    if (!spec.doc.manual_section.empty()) out << " (Player 1.5 manual section " << spec.doc.manual_section << ")";
    out << "\n";
    return;
  }
  std::size_t name_width = 4, type_width = 4, default_width = 7, unit_width = 4;
  for (const auto& option : rows) {
    name_width = std::max(name_width, option.name.size());
    type_width = std::max(type_width, option.type.size());
    default_width = std::max(default_width, option.default_value.size());
    unit_width = std::max(unit_width, option.unit.size());
  }
  out << "Options:\n  " << padded("NAME", name_width) << "  " << padded("TYPE", type_width) << "  "
      << padded("DEFAULT", default_width) << "  " << padded("UNIT", unit_width) << "  SUMMARY\n";
  for (const auto& option : rows) {
    out << "  " << padded(option.name, name_width) << "  " << padded(option.type, type_width) << "  "
        << padded(option.default_value, default_width) << "  " << padded(option.unit, unit_width) << "  "
        << option.summary << "\n";
  }
}

void write_spec_info(const core::DriverSpec& spec, std::ostream& out) {
  out << spec.name << ": " << (spec.summary.empty() ? "(no summary)" : spec.summary) << "\n";
  std::string interfaces;
  if (serves_every_interface(spec)) {
    interfaces = "any";
  } else {
    for (const auto code : spec.interfaces) {
      interfaces += (interfaces.empty() ? "" : ", ") + protocol::interface_name(code) + " (" + std::to_string(code) + ")";
    }
  }
  out << "  interfaces      " << interfaces << "\n";
  out << "  access          " << access_text(spec.access) << "\n";
  if (!spec.family.empty()) out << "  family          " << spec.family << "\n";
  out << "  needs hardware  " << (spec.doc.needs_hardware ? "yes" : "no") << "\n";
  out << "  manual          "
      << (spec.doc.manual_section.empty() ? std::string("not documented")
                                          : "section " + spec.doc.manual_section + " of the Player 1.5 manual")
      << "\n\n";
  write_options_table(spec, out);
  out << "\nRequests:";
  if (spec.doc.requests.empty()) {
    out << " not documented for this driver\n";
  } else {
    out << "\n";
    for (const auto& request : spec.doc.requests) out << "  " << request << "\n";
  }
  out << "\nConfig:\n  " << config_section(spec) << "\n";
  if (!spec.doc.unavailable.empty()) {
    // Nothing to try: the server refuses it, and says what to use instead.
    out << "\nCannot run:\n  " << spec.doc.unavailable << "\n";
    return;
  }
  out << "\nTry it:\n  player-drivers run " << spec.name;
  for (const auto& option : spec.doc.option_rows()) {
    // A serial link is shown on a USB adapter; a port that is a number (a
    // Nomad server's TCP port) with its default.
    if (option.name != "port") continue;
    const std::string& fallback = option.default_value;
    const bool number = !fallback.empty() && std::all_of(fallback.begin(), fallback.end(), [](unsigned char c) {
      return std::isdigit(c) != 0;
    });
    out << " port=" << (number ? fallback : std::string("/dev/ttyUSB0"));
  }
  out << " -n 5\n";
}

void write_family_info(const DriverSelection& selection, std::ostream& out) {
  const auto addresses = family_addresses(selection.drivers);
  out << selection.name << ": a family of " << selection.drivers.size()
      << " drivers, served together on one link by `player-drivers run " << selection.name << "`\n";
  std::size_t device_width = 0, name_width = 0;
  for (std::size_t i = 0; i < selection.drivers.size(); ++i) {
    device_width = std::max(device_width, protocol::to_string(addresses[i]).size());
    name_width = std::max(name_width, selection.drivers[i]->name.size());
  }
  for (std::size_t i = 0; i < selection.drivers.size(); ++i) {
    out << "  " << padded(protocol::to_string(addresses[i]), device_width) << "  "
        << padded(selection.drivers[i]->name, name_width) << "  " << selection.drivers[i]->summary << "\n";
  }
  out << "\nConfig (all of them; options such as port may go on any one):\n";
  for (std::size_t i = 0; i < selection.drivers.size(); ++i) {
    out << "  " << protocol::to_string(addresses[i]) << " ( driver \"" << selection.drivers[i]->name << "\" )\n";
  }
  out << "\nplayer-drivers info DRIVER shows each driver's options.\n";
}

}  // namespace

std::string access_text(protocol::Access access) {
  switch (access) {
    case protocol::Access::kRead: return "r (read: data and requests)";
    case protocol::Access::kWrite: return "w (write: commands and requests)";
    case protocol::Access::kAll: return "a (read and write)";
    default: return access_letter(access);
  }
}

std::string config_section(const core::DriverSpec& spec) {
  if (!spec.doc.example.empty()) return spec.doc.example;
  const std::uint16_t interface = spec.interfaces.empty() ? protocol::kNullCode : spec.interfaces.front();
  return protocol::interface_name(interface) + ":0 ( driver \"" + spec.name + "\" )";
}

std::size_t write_driver_list(const core::DriverRegistry& registry, const ListOptions& options, std::ostream& out) {
  std::vector<const core::DriverSpec*> shown;
  for (const auto* spec : registry.all()) {
    if (options.interface && std::find(spec->interfaces.begin(), spec->interfaces.end(), *options.interface) ==
                                 spec->interfaces.end()) {
      continue;
    }
    shown.push_back(spec);
  }
  if (options.json) {
    for (const auto* spec : shown) out << list_json(*spec).dump() << "\n";
    out << std::flush;
    return shown.size();
  }
  std::size_t name_width = 6, interface_width = 10;
  for (const auto* spec : shown) {
    name_width = std::max(name_width, spec->name.size());
    interface_width = std::max(interface_width, short_interfaces(*spec).size());
  }
  out << padded("DRIVER", name_width) << "  " << padded("INTERFACES", interface_width) << "  ACCESS  HARDWARE  SUMMARY\n";
  for (const auto* spec : shown) {
    out << padded(spec->name, name_width) << "  " << padded(short_interfaces(*spec), interface_width) << "  "
        << padded(access_letter(spec->access), 6) << "  " << padded(spec->doc.needs_hardware ? "yes" : "no", 8) << "  "
        << spec->summary << "\n";
  }
  // Families worth running as one: those of more than one driver.
  std::string families;
  for (const auto& family : family_names(registry)) {
    const auto members = family_drivers(registry, family);
    if (members.size() < 2) continue;
    families += (families.empty() ? "" : ", ") + family + " (" + std::to_string(members.size()) + " drivers)";
  }
  if (!options.interface && !families.empty()) {
    out << "\nFamilies, run together on one link with `player-drivers run FAMILY`: " << families << "\n";
  }
  out << std::flush;
  return shown.size();
}

void write_driver_info(const core::DriverRegistry& registry, std::string_view name, bool json, std::ostream& out) {
  const DriverSelection selection = select_drivers(registry, name);
  if (json) {
    nlohmann::json info;
    if (selection.family) {
      const auto addresses = family_addresses(selection.drivers);
      info = {{"family", selection.name}, {"drivers", nlohmann::json::array()}};
      for (std::size_t i = 0; i < selection.drivers.size(); ++i) {
        info["drivers"].push_back({{"device", protocol::to_string(addresses[i])},
                                   {"name", selection.drivers[i]->name},
                                   {"summary", selection.drivers[i]->summary}});
      }
    } else {
      const auto& spec = *selection.drivers.front();
      info = list_json(spec);
      info["manual_section"] = spec.doc.manual_section;
      info["options"] = options_json(spec);
      info["requests"] = spec.doc.requests;
      info["config"] = config_section(spec);
    }
    out << info.dump() << "\n" << std::flush;
    return;
  }
  if (selection.family) {
    write_family_info(selection, out);
  } else {
    write_spec_info(*selection.drivers.front(), out);
  }
  out << std::flush;
}

}  // namespace playerkit::player_drivers
