#pragma once
// The subcommands of amcl-offline, as functions of their options, so that
// main.cpp only turns flags into these structs (amcl_offline_options.hpp). Each returns the exit status
// and reports on `err`; data goes to the output file or stdout.

#include <ostream>

#include "amcl_offline_options.hpp"

namespace playerkit::amcl_offline {

int run_map(const MapOptions& options, std::ostream& err);
int run_perturb(const PerturbCommand& command, std::ostream& out, std::ostream& err);
int run_localize(const LocalizeOptions& options, std::ostream& out, std::ostream& err);

}  // namespace playerkit::amcl_offline
