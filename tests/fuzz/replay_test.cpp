// Every saved input of every fuzz target, replayed through the ordinary
// build: the seeds of tests/fuzz/corpus/<target>/ and the inputs that once
// crashed or hung, tests/fuzz/regressions/<target>/. A target that throws
// fails the test naming the file; one that aborts (a broken invariant, a
// sanitizer in a sanitized build) ends the program with the file named on
// stderr just before.

#include <gtest/gtest.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

#include "fuzz_targets.hpp"

namespace replay_test {

namespace fs = std::filesystem;
using Target = int (*)(const std::uint8_t*, std::size_t);

// Test data a target takes as seeds where it stands, instead of a copy under
// tests/fuzz/corpus (scripts/fuzz seeds from the same: seed_directories_of).
std::vector<fs::path> seed_data_of(const std::string& target) {
  if (target == "config_parser") return {fs::path(PLAYERKIT_TEST_DATA_DIR) / "config"};
  return {};
}

std::vector<fs::path> inputs_of(const std::string& target) {
  std::vector<fs::path> directories = seed_data_of(target);
  for (const char* kind : {"corpus", "regressions"}) directories.push_back(fs::path(PLAYERKIT_FUZZ_DIR) / kind / target);
  std::vector<fs::path> files;
  for (const fs::path& directory : directories) {
    if (!fs::is_directory(directory)) continue;
    for (const auto& entry : fs::directory_iterator(directory)) {
      if (entry.is_regular_file() && entry.path().extension() != ".md") files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::uint8_t> read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void replay(const std::string& name, Target target) {
  const auto files = inputs_of(name);
  ASSERT_FALSE(files.empty()) << "no saved input for " << name << " under " << PLAYERKIT_FUZZ_DIR;
  for (const auto& file : files) {
    const auto bytes = read_bytes(file);
    std::cerr << "replaying " << file.string() << " (" << bytes.size() << " bytes)\n";
    try {
      EXPECT_EQ(target(bytes.data(), bytes.size()), 0) << file;
    } catch (const std::exception& error) {
      ADD_FAILURE() << file << ": " << error.what();
    }
  }
}

TEST(FuzzReplay, FrameReader) { replay("frame_reader", playerkit::fuzz::frame_reader); }
TEST(FuzzReplay, ConfigParser) { replay("config_parser", playerkit::fuzz::config_parser); }
TEST(FuzzReplay, PlayerLogReader) { replay("player_log_reader", playerkit::fuzz::player_log_reader); }
TEST(FuzzReplay, CarmenLogReader) { replay("carmen_log_reader", playerkit::fuzz::carmen_log_reader); }
TEST(FuzzReplay, MapYaml) { replay("map_yaml", playerkit::fuzz::map_yaml); }
TEST(FuzzReplay, MapImage) { replay("map_image", playerkit::fuzz::map_image); }
TEST(FuzzReplay, WorldFile) { replay("world_file", playerkit::fuzz::world_file); }
#ifdef PLAYERKIT_FUZZ_P2OS_SIP
TEST(FuzzReplay, P2osSip) { replay("p2os_sip", playerkit::fuzz::p2os_sip); }
#endif
#ifdef PLAYERKIT_FUZZ_SICK_TELEGRAM
TEST(FuzzReplay, SickTelegram) { replay("sick_telegram", playerkit::fuzz::sick_telegram); }
#endif
TEST(FuzzReplay, JsonLine) { replay("json_line", playerkit::fuzz::json_line); }
TEST(FuzzReplay, LogInput) { replay("log_input", playerkit::fuzz::log_input); }

}  // namespace replay_test
