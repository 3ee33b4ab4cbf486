#pragma once
// The devices a tool's command line names after the server (player-cat,
// player-view): "laser:0", "position" (index 0), "6:1".

#include <string>
#include <vector>

#include "protocol/device_address.hpp"

namespace playerkit::tools {

// Throws UsageError for a word that is no device, or a device named twice.
std::vector<protocol::DeviceAddress> parse_device_arguments(const std::vector<std::string>& words);

}  // namespace playerkit::tools
