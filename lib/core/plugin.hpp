#pragma once
// Driver plugins: shared objects loaded with `player-serve -d lib.so`.
//
// A plugin defines one entry point with the macro below; the server calls it
// once with its registry, and the plugin adds its drivers:
//
//   #include "core/plugin.hpp"
//   PLAYERKIT_DRIVER_PLUGIN(registry) {
//     registry.add({.name = "mydriver", .interfaces = {protocol::kLaserCode}, ...});
//   }
//
// The plugin is C++ and talks to the server through these headers, so it must
// be built with the same playerkit headers and compiler (the ABI version below
// guards against the obvious mismatch). Build it as a MODULE library; the
// server exports the library symbols it needs (examples/plugin-driver).

#include <filesystem>
#include <stdexcept>

#include "core/driver_registry.hpp"

namespace playerkit::core {

// Bumped whenever DriverRegistry, Driver or Device change incompatibly.
inline constexpr int kPluginAbiVersion = 2;  // 2: Driver::check()

class PluginError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// dlopen()s the file (RTLD_NOW) and runs its entry point. The library stays
// loaded for the life of the process. Throws PluginError saying what went wrong.
void load_driver_plugin(const std::filesystem::path& path, DriverRegistry& registry);

}  // namespace playerkit::core

#define PLAYERKIT_DRIVER_PLUGIN(registry_name)                                          \
  extern "C" int playerkit_plugin_abi_version() {                                       \
    return ::playerkit::core::kPluginAbiVersion;                                        \
  }                                                                                     \
  static void playerkit_plugin_register(::playerkit::core::DriverRegistry&);            \
  extern "C" void playerkit_register_drivers(::playerkit::core::DriverRegistry& r) {    \
    playerkit_plugin_register(r);                                                       \
  }                                                                                     \
  static void playerkit_plugin_register(::playerkit::core::DriverRegistry& registry_name)
