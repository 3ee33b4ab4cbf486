#pragma once
// Helpers for the loader's tests (header-only, test code only).

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "sim/worldfile/world_loader.hpp"

namespace playerkit::sim::worldfile::loader_test_support {

inline std::filesystem::path worlds_dir() { return PLAYERKIT_WORLDS_DIR; }

inline WorldDescription describe_text(const std::string& text, const WorldLoadOptions& options = {}) {
  return describe_world_text(text, "t.world", worlds_dir(), options);
}

// what() of the error the text raises, or "" when it loads.
inline std::string load_error(const std::string& text) {
  try {
    describe_text(text);
  } catch (const WorldFileError& error) {
    return error.what();
  }
  return "";
}

inline const ModelSpec& model_named(const WorldDescription& world, const std::string& name) {
  for (const ModelSpec& model : world.models) {
    if (model.name == name) return model;
  }
  throw std::runtime_error("no model named " + name);
}

// "port:interface:index driver" for each device, e.g. "6665:4:0 position".
inline std::vector<std::string> device_list(const WorldDescription& world) {
  std::vector<std::string> list;
  for (const SimDevice& device : world.devices) {
    list.push_back(std::to_string(device.port) + ":" + std::to_string(device.interface_code) + ":" +
                   std::to_string(device.index) + " " + device.driver_name);
  }
  return list;
}

inline const SimDevice& device(const WorldDescription& world, std::uint16_t port, std::uint16_t code,
                               std::uint16_t index) {
  for (const SimDevice& found : world.devices) {
    if (found.port == port && found.interface_code == code && found.index == index) return found;
  }
  throw std::runtime_error("no such device");
}

constexpr double kDeg = 3.14159265358979323846 / 180.0;

}  // namespace playerkit::sim::worldfile::loader_test_support
