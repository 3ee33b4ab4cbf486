#include "sim/render/world_png.hpp"

#include <stdexcept>

#include "files/output_file.hpp"
#include "image/png.hpp"

namespace playerkit::sim::render {

std::vector<std::uint8_t> encode_png(const Picture& picture) {
  if (picture.rgb.size() != static_cast<std::size_t>(picture.width()) * static_cast<std::size_t>(picture.height()) * 3) {
    throw std::invalid_argument("encode_png: the picture's pixels do not match its size");
  }
  return image::encode_png(picture.rgb, picture.width(), picture.height(), 3);
}

void write_png(const std::filesystem::path& file, const Picture& picture,
               const std::vector<std::filesystem::path>& inputs) {
  const std::vector<std::uint8_t> encoded = encode_png(picture);
  files::OutputFile out(file, {.inputs = inputs, .compression = files::Compression::kNone});
  out.stream().write(reinterpret_cast<const char*>(encoded.data()), static_cast<std::streamsize>(encoded.size()));
  out.commit();
}

void write_world_png(const std::filesystem::path& file, const World& world, const Trails* trails,
                     const PictureOptions& options, const std::vector<std::filesystem::path>& inputs) {
  write_png(file, draw_world(take_snapshot(world, trails), options), inputs);
}

}  // namespace playerkit::sim::render
