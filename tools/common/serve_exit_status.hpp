#pragma once
// The daemon's outcome as a tool's exit status (exit_status.hpp).

#include "daemon/serve.hpp"
#include "exit_status.hpp"

namespace playerkit::tools {

inline int exit_status_for(daemon::ServeResult result) {
  switch (result) {
    case daemon::ServeResult::stopped: return kExitOk;
    case daemon::ServeResult::bad_configuration: return kExitUsage;
    case daemon::ServeResult::failed: break;
  }
  return kExitFailure;
}

}  // namespace playerkit::tools
