#include "map/map_file.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

namespace playerkit::map {
namespace map_file_test {

using grid::CellState;
namespace fs = std::filesystem;

// Each test gets its own empty folder, removed afterwards.
class MapFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::temp_directory_path() /
              ("playerkit_map_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  fs::path path(const std::string& name) const { return folder_ / name; }

  // Rows top first, as in the file.
  fs::path write_pgm(const std::string& name, int width, int height,
                     const std::vector<std::uint8_t>& pixels) const {
    return write_pnm(name, "P5", width, height, pixels);
  }
  fs::path write_pnm(const std::string& name, const char* magic, int width, int height,
                     const std::vector<std::uint8_t>& bytes) const {
    const fs::path file = path(name);
    fs::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out << magic << "\n" << width << " " << height << "\n255\n";
    out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    return file;
  }
  fs::path write_text(const std::string& name, const std::string& text) const {
    const fs::path file = path(name);
    fs::create_directories(file.parent_path());
    std::ofstream(file) << text;
    return file;
  }

  fs::path folder_;
};

std::string error_of(const fs::path& file, const MapLoadOptions& options = {}) {
  try {
    (void)load_map(file, options);
  } catch (const MapFileError& error) {
    return error.what();
  }
  return "no error";
}

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

std::size_t count(const grid::OccupancyGrid& grid, CellState state) {
  return static_cast<std::size_t>(std::count(grid.cells().begin(), grid.cells().end(), state));
}

// occupancy (255 - v) / 255: 1, .902, .8, .498, .2, .098, 0
const std::vector<std::uint8_t> kRamp = {0, 25, 51, 128, 204, 230, 255};

TEST_F(MapFileTest, PgmPixelsBecomeCellStatesWithBottomRowFirst) {
  const fs::path file = write_pgm("small.pgm", 3, 2, {0, 255, 205,  /* top */ 128, 10, 250});
  const grid::OccupancyGrid grid = load_map(file, {.resolution = 0.5});
  ASSERT_EQ(grid.width(), 3);
  ASSERT_EQ(grid.height(), 2);
  EXPECT_DOUBLE_EQ(grid.resolution(), 0.5);
  // The image's top row is the grid's last row.
  EXPECT_EQ(grid.at(0, 1), CellState::occupied);  // 0: black
  EXPECT_EQ(grid.at(1, 1), CellState::free);      // 255: white
  EXPECT_EQ(grid.at(2, 1), CellState::unknown);   // 205: map_saver's unknown, p = 0.19608
  EXPECT_EQ(grid.at(0, 0), CellState::unknown);   // 128
  EXPECT_EQ(grid.at(1, 0), CellState::occupied);  // 10
  EXPECT_EQ(grid.at(2, 0), CellState::free);      // 250
}

TEST_F(MapFileTest, NegateSwapsTheMeaningOfBlackAndWhite) {
  const fs::path file = write_pgm("small.pgm", 3, 2, {0, 255, 205, 128, 10, 250});
  const grid::OccupancyGrid grid = load_map(file, {.resolution = 0.5, .negate = true});
  EXPECT_EQ(grid.at(0, 1), CellState::free);
  EXPECT_EQ(grid.at(1, 1), CellState::occupied);
  EXPECT_EQ(grid.at(2, 1), CellState::occupied);  // p = 0.804
  EXPECT_EQ(grid.at(0, 0), CellState::unknown);   // p = 0.502
  EXPECT_EQ(grid.at(1, 0), CellState::free);
  EXPECT_EQ(grid.at(2, 0), CellState::occupied);
}

TEST_F(MapFileTest, ThresholdsAreStrict) {
  const fs::path file = write_pgm("ramp.pgm", 7, 1, kRamp);
  auto states = [&](const MapLoadOptions& options) {
    const grid::OccupancyGrid grid = load_map(file, options);
    return std::vector<CellState>(grid.cells().begin(), grid.cells().end());
  };
  using enum CellState;
  EXPECT_EQ(states({.resolution = 1.0}),
            (std::vector{occupied, occupied, occupied, unknown, unknown, free, free}));
  EXPECT_EQ(states({.resolution = 1.0, .occupied_threshold = 0.9, .free_threshold = 0.1}),
            (std::vector{occupied, occupied, unknown, unknown, unknown, free, free}));
  EXPECT_EQ(states({.resolution = 1.0, .occupied_threshold = 0.95, .free_threshold = 0.05}),
            (std::vector{occupied, unknown, unknown, unknown, unknown, unknown, free}));
}

TEST_F(MapFileTest, PlainImagesAreCentredOnTheWorldOrigin) {
  const fs::path file = write_pgm("centred.pgm", 4, 6, std::vector<std::uint8_t>(24, 255));
  const grid::OccupancyGrid grid = load_map(file, {.resolution = 0.25});
  EXPECT_DOUBLE_EQ(grid.origin().x(), -0.5);
  EXPECT_DOUBLE_EQ(grid.origin().y(), -0.75);
  EXPECT_EQ(grid.world_to_cell({0.01, 0.01}), Eigen::Vector2i(2, 3));
}

TEST_F(MapFileTest, AnOriginPlacesThePlainImagesBottomLeftCorner) {
  // 4 x 6 pixels, one black pixel at the top left (column 0, row 0 of the image).
  std::vector<std::uint8_t> pixels(24, 255);
  pixels[0] = 0;
  const fs::path file = write_pgm("placed.pgm", 4, 6, pixels);
  const grid::OccupancyGrid grid = load_map(file, {.resolution = 0.25, .origin = Eigen::Vector2d(0.0, 0.0)});
  EXPECT_DOUBLE_EQ(grid.origin().x(), 0.0);
  EXPECT_DOUBLE_EQ(grid.origin().y(), 0.0);
  // The image's top row is the grid's highest: y in [1.25, 1.5).
  EXPECT_EQ(grid.state_at_world({0.1, 1.4}), CellState::occupied);
  EXPECT_EQ(grid.state_at_world({0.1, 0.1}), CellState::free);
  EXPECT_EQ(grid.state_at_world({-0.1, 0.1}), CellState::unknown);  // outside
  const grid::OccupancyGrid shifted = load_map(file, {.resolution = 0.25, .origin = Eigen::Vector2d(-2.0, 3.0)});
  EXPECT_EQ(shifted.state_at_world({-1.9, 4.4}), CellState::occupied);
  const std::string error =
      error_of(file, {.resolution = 0.25, .origin = Eigen::Vector2d(std::nan(""), 0.0)});
  EXPECT_NE(error.find("origin must be finite"), std::string::npos) << error;
}

TEST_F(MapFileTest, ColourImagesAreReadAsGrey) {
  // P6: white, black, mid grey, pure blue (grey 29: dark, so occupied).
  const fs::path file = write_pnm("colour.ppm", "P6", 4, 1,
                                  {255, 255, 255, 0, 0, 0, 128, 128, 128, 0, 0, 255});
  const grid::OccupancyGrid grid = load_map(file, {.resolution = 0.1});
  EXPECT_EQ(grid.at(0, 0), CellState::free);
  EXPECT_EQ(grid.at(1, 0), CellState::occupied);
  EXPECT_EQ(grid.at(2, 0), CellState::unknown);
  EXPECT_EQ(grid.at(3, 0), CellState::occupied);
}

TEST_F(MapFileTest, PlainImageErrors) {
  const fs::path file = write_pgm("a.pgm", 1, 1, {0});
  EXPECT_TRUE(starts_with(error_of(file), file.string() + ": a plain map image needs a resolution"))
      << error_of(file);
  EXPECT_TRUE(starts_with(error_of(file, {.resolution = -1.0}), file.string() + ": "));
  EXPECT_EQ(error_of(path("missing.pgm"), {.resolution = 1.0}), path("missing.pgm").string() + ": no such file");
  const fs::path junk = write_text("junk.png", "not an image");
  EXPECT_EQ(error_of(junk, {.resolution = 1.0}),
            junk.string() + ": cannot read as an image: not a PNG, PGM, PPM or PBM image (convert other formats to PNG)");
  // What is wrong with a damaged image is said.
  const fs::path cut = write_text("cut.pgm", "P5 4 4 255\nab");
  EXPECT_EQ(error_of(cut, {.resolution = 1.0}),
            cut.string() + ": cannot read as an image: PNM: the pixels are truncated (2 of 16 bytes)");
}

TEST_F(MapFileTest, YamlGivesResolutionOriginNegateAndThresholds) {
  write_pgm("images/ramp.pgm", 7, 1, kRamp);
  const fs::path yaml = write_text("ramp.yaml",
                                   "image: images/ramp.pgm\n"
                                   "resolution: 0.1\n"
                                   "origin: [-12.5, 3.25, 0.0]\n"
                                   "negate: 1\n"
                                   "occupied_thresh: 0.9\n"
                                   "free_thresh: 0.1\n"
                                   "mode: trinary\n"
                                   "unknown_key: [whatever, 1]\n");
  // Image options do not apply to YAML maps.
  const grid::OccupancyGrid grid = load_map(yaml, {.resolution = 5.0, .negate = false});
  EXPECT_DOUBLE_EQ(grid.resolution(), 0.1);
  EXPECT_DOUBLE_EQ(grid.origin().x(), -12.5);
  EXPECT_DOUBLE_EQ(grid.origin().y(), 3.25);
  using enum CellState;
  // Negated occupancy v/255: 0, .098, .2, .502, .8, .902, 1.
  EXPECT_EQ(std::vector<CellState>(grid.cells().begin(), grid.cells().end()),
            (std::vector{free, free, unknown, unknown, unknown, occupied, occupied}));
}

TEST_F(MapFileTest, YamlErrorsCarryLineAndColumn) {
  write_pgm("m.pgm", 1, 1, {0});
  const std::string good_head = "image: m.pgm\nresolution: 0.05\n";
  const std::string good_tail = "negate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n";
  struct Case {
    std::string text;
    std::string expected;  // after "<file>:"
  };
  const Case cases[] = {
      {good_head + "origin: [0.0, 0.0, 0.5]\n" + good_tail,
       "3:20: origin yaw 0.5 is not supported: rotated maps cannot be represented (rotate the image instead)"},
      {"image: m.pgm\nresolution: fine\norigin: [0, 0, 0]\n" + good_tail,
       "2:13: resolution must be a number, got 'fine'"},
      {good_head + "origin: [0, 0]\n" + good_tail,
       "3:9: origin must be a list of three numbers [x, y, yaw]"},
      {good_head + "origin: [0, x, 0]\n" + good_tail, "3:13: origin y must be a number, got 'x'"},
      {good_head + good_tail, "1:1: missing required key 'origin'"},
      {good_head + "origin: [0, 0, 0]\n" + good_tail + "mode: scale\n",
       "7:7: mode 'scale' is not supported: only trinary maps can be loaded"},
      {good_head + "origin: [0, 0, 0]\nnegate: 2\noccupied_thresh: 0.65\nfree_thresh: 0.196\n",
       "4:9: negate must be 0 or 1, got '2'"},
      {good_head + "origin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.1\nfree_thresh: 0.196\n",
       "6:14: free_thresh is above occupied_thresh"},
      {"image: nothing.pgm\nresolution: 0.05\norigin: [0, 0, 0]\n" + good_tail,
       "1:8: cannot read image '" + path("nothing.pgm").string() + "': no such file"},
      {"image: m.pgm\n  resolution: 0.05\n", "2:3: indented line: nested values are not supported in a map file"},
  };
  for (const Case& c : cases) {
    const fs::path yaml = write_text("bad.yaml", c.text);
    EXPECT_EQ(error_of(yaml), yaml.string() + ":" + c.expected) << c.text;
  }
}

TEST_F(MapFileTest, SaveThenLoadGivesTheSameGrid) {
  grid::OccupancyGrid original(37, 23, 0.05, {-3.3, 7.1});
  std::mt19937 random(3);
  std::uniform_int_distribution<int> state(-1, 1);
  for (CellState& cell : original.cells()) cell = static_cast<CellState>(state(random));

  const fs::path pgm = path("saved map.pgm");
  save_map(original, pgm);
  ASSERT_TRUE(fs::exists(path("saved map.yaml")));
  const grid::OccupancyGrid loaded = load_map(path("saved map.yaml"));
  ASSERT_EQ(loaded.width(), original.width());
  ASSERT_EQ(loaded.height(), original.height());
  EXPECT_EQ(loaded.resolution(), original.resolution());
  EXPECT_EQ(loaded.origin(), original.origin());
  EXPECT_TRUE(std::equal(loaded.cells().begin(), loaded.cells().end(), original.cells().begin()));

  std::ifstream yaml_in(path("saved map.yaml"));
  const std::string yaml((std::istreambuf_iterator<char>(yaml_in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(yaml,
            "image: \"saved map.pgm\"\nresolution: 0.05\norigin: [-3.3, 7.1, 0.0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");

  // map_saver's pixel values, top image row = last grid row.
  const grid::OccupancyGrid as_image = load_map(pgm, {.resolution = 1.0});  // also a plain image
  EXPECT_TRUE(std::equal(as_image.cells().begin(), as_image.cells().end(), original.cells().begin()));
  std::ifstream pgm_in(pgm, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(pgm_in)), std::istreambuf_iterator<char>());
  const std::string pixels = bytes.substr(bytes.size() - 37 * 23);
  auto expected_pixel = [](CellState s) {
    return s == CellState::free ? '\xfe' : s == CellState::occupied ? '\x00' : '\xcd';
  };
  EXPECT_EQ(pixels[0], expected_pixel(original.at(0, 22)));
  EXPECT_EQ(pixels[36], expected_pixel(original.at(36, 22)));
  EXPECT_EQ(pixels[37 * 22], expected_pixel(original.at(0, 0)));
  EXPECT_EQ(std::count(pixels.begin(), pixels.end(), '\xcd'),
            static_cast<long>(count(original, CellState::unknown)));
}

TEST_F(MapFileTest, SavingOverAnOlderMapReplacesItAndLeavesNothingElse) {
  grid::OccupancyGrid small(2, 2, 0.1, {0.0, 0.0});
  grid::OccupancyGrid large(40, 30, 0.1, {0.0, 0.0});
  save_map(large, path("map.pgm"));
  save_map(small, path("map.pgm"));
  EXPECT_EQ(load_map(path("map.yaml")).width(), 2);
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(folder_)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"map.pgm", "map.yaml"}));  // no temporaries left
}

TEST(PlayerMaps, CavePnmLoadsWithPlayersScaleAndNegate) {
  const fs::path file = fs::path(PLAYERKIT_TEST_DATA_DIR) / "maps" / "cave.pnm";
  // As Player's own test_localize.cfg: map_scale 0.03, map_negate 1.
  const grid::OccupancyGrid grid = load_map(file, {.resolution = 0.03, .negate = true});
  ASSERT_EQ(grid.width(), 500);
  ASSERT_EQ(grid.height(), 500);
  EXPECT_DOUBLE_EQ(grid.origin().x(), -7.5);
  EXPECT_DOUBLE_EQ(grid.origin().y(), -7.5);
  EXPECT_EQ(count(grid, CellState::occupied), 5269u);  // about 2 % wall
  EXPECT_EQ(count(grid, CellState::free), 244731u);
  EXPECT_EQ(count(grid, CellState::unknown), 0u);

  auto occupied_in_row = [&](int row) {
    int n = 0;
    for (int col = 0; col < grid.width(); ++col) n += grid.at(col, row) == CellState::occupied;
    return n;
  };
  EXPECT_EQ(occupied_in_row(499), 83);  // the image's top row
  EXPECT_EQ(occupied_in_row(0), 113);   // its bottom row

  const grid::OccupancyGrid not_negated = load_map(file, {.resolution = 0.03});
  EXPECT_EQ(count(not_negated, CellState::occupied), 244731u);
}

TEST(PlayerMaps, StageCavePngIsTheSameCaveWithoutNegate) {
  const fs::path data = fs::path(PLAYERKIT_TEST_DATA_DIR) / "maps";
  const grid::OccupancyGrid png = load_map(data / "stage-cave.png", {.resolution = 0.032});
  const grid::OccupancyGrid pnm = load_map(data / "cave.pnm", {.resolution = 0.03, .negate = true});
  ASSERT_EQ(png.width(), 500);
  ASSERT_EQ(png.height(), 500);
  EXPECT_EQ(count(png, CellState::occupied), 5270u);
  EXPECT_EQ(count(png, CellState::free), 244730u);
  int differing = 0;
  for (std::size_t i = 0; i < png.cells().size(); ++i) differing += png.cells()[i] != pnm.cells()[i];
  EXPECT_LE(differing, 10);
}

}  // namespace map_file_test
}  // namespace playerkit::map
