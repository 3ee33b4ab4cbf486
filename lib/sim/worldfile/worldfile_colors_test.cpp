#include "sim/worldfile/worldfile_colors.hpp"

#include <gtest/gtest.h>

namespace playerkit::sim::worldfile {
namespace worldfile_colors_test {

// Values from X11's rgb.txt.
TEST(WorldfileColors, NamesStageWorldsUse) {
  EXPECT_EQ(x11_color("red"), (Rgb{255, 0, 0}));
  EXPECT_EQ(x11_color("green"), (Rgb{0, 255, 0}));
  EXPECT_EQ(x11_color("gray"), (Rgb{190, 190, 190}));
  EXPECT_EQ(x11_color("grey"), (Rgb{190, 190, 190}));
  EXPECT_EQ(x11_color("gray30"), (Rgb{77, 77, 77}));
  EXPECT_EQ(x11_color("grey50"), (Rgb{127, 127, 127}));
  EXPECT_EQ(x11_color("gray0"), (Rgb{0, 0, 0}));
  EXPECT_EQ(x11_color("gray1"), (Rgb{3, 3, 3}));
  EXPECT_EQ(x11_color("gray85"), (Rgb{217, 217, 217}));
  EXPECT_EQ(x11_color("gray100"), (Rgb{255, 255, 255}));
  EXPECT_EQ(x11_color("LightBlue"), (Rgb{173, 216, 230}));
  EXPECT_EQ(x11_color("light blue"), (Rgb{173, 216, 230}));
  EXPECT_EQ(x11_color("orange"), (Rgb{255, 165, 0}));
  EXPECT_EQ(x11_color("purple"), (Rgb{160, 32, 240}));
  EXPECT_EQ(x11_color("dark green"), (Rgb{0, 100, 0}));
  EXPECT_EQ(x11_color("blue3"), (Rgb{0, 0, 205}));
}

TEST(WorldfileColors, MatchIsExact) {
  EXPECT_FALSE(x11_color("Red"));  // case-sensitive, as in Stage
  EXPECT_FALSE(x11_color("lightblue"));
  EXPECT_FALSE(x11_color("gray101"));
  EXPECT_FALSE(x11_color("gray05"));
  EXPECT_FALSE(x11_color("gray"
                         "x"));
  EXPECT_FALSE(x11_color(""));
}

}  // namespace worldfile_colors_test
}  // namespace playerkit::sim::worldfile
