#pragma once
// The --help footers of player-drivers and its subcommands. What depends on
// the hardware families built (their examples, probes and emulators) comes
// from the family registry, so a family left out of the build is never named.

#include <string>

#include "families/family_registry.hpp"

namespace playerkit::player_drivers {

std::string main_footer(const families::FamilyRegistry& families);
std::string run_footer(const families::FamilyRegistry& families);
std::string probe_footer(const families::FamilyRegistry& families);
std::string emulate_footer(const families::FamilyRegistry& families);

}  // namespace playerkit::player_drivers
