#include "core/plugin.hpp"

#include <dlfcn.h>

#include <string>

namespace playerkit::core {

void load_driver_plugin(const std::filesystem::path& path, DriverRegistry& registry) {
  // dlopen searches the library path for bare names; a name with a slash is a file.
  std::string name = path.string();
  void* handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = dlerror();
    throw PluginError("cannot load plugin " + name + ": " + (why ? why : "unknown error"));
  }
  using AbiFunction = int (*)();
  using RegisterFunction = void (*)(DriverRegistry&);
  auto abi = reinterpret_cast<AbiFunction>(dlsym(handle, "playerkit_plugin_abi_version"));
  auto register_drivers =
      reinterpret_cast<RegisterFunction>(dlsym(handle, "playerkit_register_drivers"));
  if (abi == nullptr || register_drivers == nullptr) {
    dlclose(handle);
    throw PluginError("plugin " + name +
                      " has no playerkit entry point (define it with PLAYERKIT_DRIVER_PLUGIN)");
  }
  if (const int version = abi(); version != kPluginAbiVersion) {
    dlclose(handle);
    throw PluginError("plugin " + name + " was built for plugin ABI " + std::to_string(version) +
                      ", this server has " + std::to_string(kPluginAbiVersion));
  }
  try {
    register_drivers(registry);
  } catch (const std::exception& e) {
    throw PluginError("plugin " + name + " failed to register its drivers: " + e.what());
  }
}

}  // namespace playerkit::core
