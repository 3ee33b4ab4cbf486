#pragma once
// Temporaries that a fatal signal must not leave behind. A program killed by
// SIGINT, SIGTERM or SIGHUP with no handler of its own (amcl-offline,
// player-log convert) would leave its half-written NAME.tmp-XXXXXX files: the
// handler installed here removes them, then dies of the signal as before. A
// program that handles these signals itself (a recorder stopping cleanly)
// keeps its handler: its own code removes or commits the files. SIGKILL
// cannot be caught; the temporary is then left, and the target untouched.

#include <string>

namespace playerkit::files {

// Remembers `path` (at most 32 at once; more are just not removed on a
// signal). Returns the slot to forget it with, or -1.
int remember_temporary(const std::string& path);
void forget_temporary(int slot);

}  // namespace playerkit::files
