#pragma once
// Shared by the localization tests: the bundled logs, and temporary files
// that remove themselves.

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include "support/scratch_directory.hpp"
#include <unistd.h>

namespace playerkit::localization::testing {

inline std::filesystem::path radish(const std::string& name) {
  return std::filesystem::path(PLAYERKIT_TEST_DATA_DIR) / "radish" / name;
}

// A directory of its own per test, removed at the end.
using TemporaryDirectory = ::playerkit::testing::ScratchDirectory;

inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace playerkit::localization::testing
