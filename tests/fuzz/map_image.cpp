// A map image through map::load_map, as amcl's map_file and player-serve's
// worlds load one: the bytes are written to a file of the scratch directory
// (load_map takes a path) and read with Player's map_scale. The size check
// that refuses huge images reads the header (image_size_from_header); a
// grid loaded must have the size that header declared.
//
// Images are refused above grid::kMaxGridCells (50 M) pixels; one just
// under it takes seconds to decode under the sanitizers, so inputs whose
// header declares more than kMaxFuzzPixels are only size-checked (tightening
// the input, not the library: the library's limit is tested in lib/map).

#include <fstream>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "map/image_header.hpp"
#include "map/map_file.hpp"

namespace playerkit::fuzz {
namespace map_image_detail {

constexpr long long kMaxFuzzPixels = 1 << 20;

// Each side bounded before the product: a header may declare sides of up to
// 2^32 - 1 (a PNG's u32 fields, a PNM's numbers), whose product overflows a
// long long, and this test must not rely on the library having refused them.
bool too_large_to_decode_here(const map::ImageSize& size) {
  return size.width > kMaxFuzzPixels || size.height > kMaxFuzzPixels ||
         size.width * size.height > kMaxFuzzPixels;
}

}  // namespace map_image_detail

int map_image(const std::uint8_t* data, std::size_t size) {
  const auto header = map::image_size_from_header_bytes(as_text({data, size}));
  if (header && map_image_detail::too_large_to_decode_here(*header)) return 0;
  const auto file = scratch_directory() / "fuzz-map.img";
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const auto grid = map::load_map(file, {.resolution = 0.05});
    if (header && (grid.width() != header->width || grid.height() != header->height)) {
      invariant_failed("map_image", "a loaded grid of another size than its header declares");
    }
  } catch (const map::MapFileError&) {
  }
  return 0;
}

}  // namespace playerkit::fuzz
