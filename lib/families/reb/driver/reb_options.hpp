#pragma once
// The reb drivers' options (reb.md §4). The robot's options (`port`,
// `subclass`) may be written on any one of its sections, as 1.5 read
// `port` from every section (1.5 read `subclass` only from reb_position's,
// which is where its configurations write it).

#include <string>
#include <string_view>

#include "core/driver.hpp"
#include "core/driver_registry.hpp"
#include "core/option_schema.hpp"

namespace playerkit::drivers::reb {

enum class RebRole { position, ir, power };
[[nodiscard]] std::string_view driver_name(RebRole role);

inline constexpr std::string_view kDefaultRebPort = "/dev/ttySA1";

struct RebLinkOptions {
  std::string port{kDefaultRebPort};
  std::string subclass = "slow";
};

[[nodiscard]] const core::OptionSchema& reb_option_schema(RebRole role);
[[nodiscard]] RebLinkOptions read_reb_link_options(const core::DriverContext& context);
// reb_position's own: heading control (1.5's default) or direct velocities.
[[nodiscard]] bool read_heading_control(const core::DriverContext& context);
[[nodiscard]] std::string connection_key(const RebLinkOptions& options);

}  // namespace playerkit::drivers::reb
