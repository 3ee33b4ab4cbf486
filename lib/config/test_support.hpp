#pragma once
// Shared by the *_test.cpp files of this directory.

#include <string>

#include "config/errors.hpp"

namespace playerkit::config::testing {

// Absolute path of tests/data/config, or of a file in it.
inline std::string data_path(const std::string& name = "") {
  const std::string directory = std::string(PLAYERKIT_TEST_DATA_DIR) + "/config";
  return name.empty() ? directory : directory + "/" + name;
}

// The what() of the ConfigError that `action` throws, or "no error".
template <typename Action>
std::string error_of(Action&& action) {
  try {
    action();
  } catch (const ConfigError& error) {
    return error.what();
  }
  return "no error";
}

}  // namespace playerkit::config::testing
