#pragma once
// The driver names a stock Player 1.5 server knows: every driver documented in
// chapter 7 of the manual, under the name a config file uses (the manual
// prints underscores as spaces: "p2os position" is p2os_position), plus the
// default drivers of wire-format.md §4 that the chapter does not document
// (camerav4l and the Stage drivers stg_simulation, stg_blinkenlight).

#include <span>
#include <string_view>

namespace playerkit::config {

// Sorted by name, like the driver list in 1.5's usage text.
std::span<const std::string_view> player15_drivers();

bool is_player15_driver(std::string_view name);

}  // namespace playerkit::config
