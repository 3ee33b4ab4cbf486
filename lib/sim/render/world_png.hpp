#pragma once
// A picture of a world written as a PNG file, through lib/files: never over
// one of the program's inputs, atomically (a temporary renamed into place),
// whatever the name's extension (never gzip).
//
//   render::write_world_png("world.png", world, &trails, {}, {world_file});

#include <cstdint>
#include <filesystem>
#include <vector>

#include "sim/render/trails.hpp"
#include "sim/render/world_picture.hpp"
#include "sim/world/world.hpp"

namespace playerkit::sim::render {

[[nodiscard]] std::vector<std::uint8_t> encode_png(const Picture& picture);

// Throws files::OutputIsInputError when `file` is one of `inputs`,
// files::OutputError when it cannot be written (the previous file stays).
void write_png(const std::filesystem::path& file, const Picture& picture,
               const std::vector<std::filesystem::path>& inputs = {});

// take_snapshot, draw_world and write_png in one: the caller holds the world
// still meanwhile.
void write_world_png(const std::filesystem::path& file, const World& world, const Trails* trails = nullptr,
                     const PictureOptions& options = {}, const std::vector<std::filesystem::path>& inputs = {});

}  // namespace playerkit::sim::render
