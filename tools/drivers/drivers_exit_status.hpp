#pragma once
// player-drivers' exit statuses: tools/common's table, with player-send's
// reply codes for `run --req` and `run --stdin`.

#include "exit_status.hpp"

namespace playerkit::player_drivers {

using tools::kExitError;    // 4: run --req: the server answered ERR (no such device, no access)
using tools::kExitFailure;  // 1: the work failed (a port, a device, the daemon, a map); probe: a port not identified
using tools::kExitNack;     // 3: run --req: the device refused (NACK)
using tools::kExitOk;       // 0
using tools::kExitUsage;    // 2: bad flags, unknown driver or emulator, an option the driver refuses
using tools::UsageError;

}  // namespace playerkit::player_drivers
