#include "driver_lookup.hpp"

#include <algorithm>
#include <set>

#include "config/closest_name.hpp"
#include "drivers_exit_status.hpp"
#include "protocol/interfaces.hpp"
#include "text/printable.hpp"

namespace playerkit::player_drivers {

namespace {

// p2os_position: named after one of the interfaces it serves.
bool named_after_its_interface(const core::DriverSpec& spec) {
  const std::string prefix = spec.family + "_";
  if (!spec.name.starts_with(prefix)) return false;
  const std::string_view suffix = std::string_view(spec.name).substr(prefix.size());
  return std::any_of(spec.interfaces.begin(), spec.interfaces.end(),
                     [suffix](std::uint16_t code) { return protocol::interface_name(code) == suffix; });
}

}  // namespace

std::vector<const core::DriverSpec*> family_drivers(const core::DriverRegistry& registry, std::string_view family) {
  std::vector<const core::DriverSpec*> members;
  for (const auto* spec : registry.all()) {
    if (!family.empty() && spec->family == family) members.push_back(spec);
  }
  // all() is sorted by name; a stable partition keeps that order in each group.
  std::stable_partition(members.begin(), members.end(),
                        [](const core::DriverSpec* spec) { return named_after_its_interface(*spec); });
  return members;
}

std::vector<std::string> family_names(const core::DriverRegistry& registry) {
  std::set<std::string> names;
  for (const auto* spec : registry.all()) {
    if (!spec->family.empty()) names.insert(spec->family);
  }
  return {names.begin(), names.end()};
}

DriverSelection select_drivers(const core::DriverRegistry& registry, std::string_view name) {
  if (const auto* spec = registry.find(name)) return {std::string(name), false, {spec}};
  auto members = family_drivers(registry, name);
  if (!members.empty()) return {std::string(name), true, std::move(members)};

  std::vector<std::string> candidates;
  for (const auto* spec : registry.all()) candidates.push_back(spec->name);
  for (auto& family : family_names(registry)) candidates.push_back(std::move(family));
  const std::vector<std::string_view> views(candidates.begin(), candidates.end());
  std::string message = "no driver or driver family '" + text::excerpt(name) + "'";
  if (const auto nearest = config::closest_name(name, views)) message += "; did you mean '" + *nearest + "'?";
  throw UsageError(message + " (player-drivers list shows them all)");
}

}  // namespace playerkit::player_drivers
