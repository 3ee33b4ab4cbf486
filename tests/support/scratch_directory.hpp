#pragma once
// A directory of its own for one test (files, symlinks to ptys, missing
// ports), made with mkdtemp under the system's temporary directory and
// removed with everything in it afterwards. Header-only.
//
//   testing::ScratchDirectory scratch("links_test");
//   const auto log = scratch.write("run.log", "...");

#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>

namespace playerkit::testing {

class ScratchDirectory {
 public:
  explicit ScratchDirectory(std::string_view tag = "playerkit") {
    std::string pattern = (std::filesystem::temp_directory_path() / (std::string(tag) + ".XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed for " + pattern);
    path_ = pattern;
  }
  ~ScratchDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDirectory(const ScratchDirectory&) = delete;
  ScratchDirectory& operator=(const ScratchDirectory&) = delete;

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  // The path of a file in it (not created).
  [[nodiscard]] std::filesystem::path file(const std::string& name) const { return path_ / name; }
  // Writes `text` to a file in it; returns its path.
  std::filesystem::path write(const std::string& name, const std::string& text) const {
    const auto written = path_ / name;
    std::ofstream(written, std::ios::binary) << text;
    return written;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace playerkit::testing
