#include "sim/render/world_png.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

#include "files/output_file.hpp"

namespace playerkit::sim::render {

std::vector<std::uint8_t> encode_png(const Picture& picture) {
  if (picture.rgb.size() != static_cast<std::size_t>(picture.width()) * static_cast<std::size_t>(picture.height()) * 3) {
    throw std::invalid_argument("encode_png: the picture's pixels do not match its size");
  }
  // OpenCV's Mat header over the picture's bytes; cvtColor copies.
  const cv::Mat rgb(picture.height(), picture.width(), CV_8UC3, const_cast<std::uint8_t*>(picture.rgb.data()));
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  std::vector<std::uint8_t> encoded;
  if (!cv::imencode(".png", bgr, encoded)) throw std::runtime_error("cannot encode the picture as PNG");
  return encoded;
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
