// A Stage world file through sim::worldfile (describe_world_text, then
// make_world), as `player-serve -s` loads one. Includes and bitmaps are
// looked up in the scratch directory, which holds one small bitmap under
// the names data/worlds' examples use; the text's '/' are made '_', so no
// name reaches another directory.

#include <fstream>
#include <string>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "sim/worldfile/world_loader.hpp"
#include "sim/worldfile/worldfile_error.hpp"

namespace playerkit::fuzz {
namespace world_file_detail {

// An 8 x 8 grey image with a wall along its left column.
void write_bitmaps(const std::filesystem::path& directory) {
  std::string pgm = "P5\n8 8\n255\n";
  for (int row = 0; row < 8; ++row) {
    for (int col = 0; col < 8; ++col) pgm += static_cast<char>(col == 0 ? 0 : 255);
  }
  for (const char* name : {"cave.pnm", "stage-cave.png", "stage-autolab.png"}) {
    std::ofstream(directory / name, std::ios::binary) << pgm;
  }
}

const std::filesystem::path& world_directory() {
  static const std::filesystem::path directory = [] {
    write_bitmaps(scratch_directory());
    return scratch_directory();
  }();
  return directory;
}

}  // namespace world_file_detail

int world_file(const std::uint8_t* data, std::size_t size) {
  const std::string text = without_slashes(as_text({data, size}));
  try {
    auto description =
        sim::worldfile::describe_world_text(text, "fuzz.world", world_file_detail::world_directory(), {.seed = 1});
    const std::size_t devices = description.devices.size();
    const auto loaded = sim::worldfile::make_world(std::move(description));
    if (loaded.devices.size() != devices) {
      invariant_failed("world_file", "make_world offers another number of devices than described");
    }
  } catch (const sim::worldfile::WorldFileError&) {
  }
  return 0;
}

}  // namespace playerkit::fuzz
