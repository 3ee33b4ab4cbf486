#pragma once
// `player-serve --check`: load a configuration and describe what it would serve,
// without opening any port.

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>

namespace playerkit::serve {

// Prints the devices of the file to out, warnings to err. Drivers are checked
// against Player 1.5's catalog, so a configuration written for 1.5 validates;
// those `available` does not know are marked "not in this build". Returns the
// exit status: 0 when the file is valid, 2 when it is not (the error goes to err).
int check_config(const std::string& path, std::uint16_t default_port,
                 const std::function<bool(std::string_view)>& available, std::ostream& out,
                 std::ostream& err);

}  // namespace playerkit::serve
