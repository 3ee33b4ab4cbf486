#pragma once
// `player-serve --check`: load a configuration and describe what it would serve,
// without opening any port.

#include <cstdint>
#include <iosfwd>
#include <string>

namespace playerkit::serve {

// Prints the devices of the file to out, warnings to err. Returns the exit
// status: 0 when the file is valid, 2 when it is not (the error goes to err).
int check_config(const std::string& path, std::uint16_t default_port, std::ostream& out,
                 std::ostream& err);

}  // namespace playerkit::serve
