#include "families/sick/driver/sick_scan_conversion.hpp"

#include <gtest/gtest.h>

#include "protocol/binary_codec.hpp"

namespace playerkit::drivers::sick_laser {
namespace sick_scan_conversion_test {

namespace sick = hardware::sick;

// Value i reads 1000 + i steps with reflector level i % 8.
sick::Scan ramp(std::size_t count) {
  sick::Scan scan;
  for (std::size_t i = 0; i < count; ++i) {
    scan.values.push_back(sick::make_value(static_cast<std::uint16_t>(1000 + i), static_cast<std::uint8_t>(i % 8)));
  }
  return scan;
}

ScanConversion lms(int range_res, sick::Unit unit) {
  ScanConversion conversion;
  conversion.config = default_scan_config(Model::lms200);
  conversion.config.range_res = range_res;
  conversion.device_unit = unit;
  return conversion;
}

TEST(SickScanConversion, MillimetresAsTheyComeWithTheSheetsAnglesAndReflectorLevels) {
  const protocol::LaserData data = to_laser_data(ramp(361), lms(1, sick::Unit::millimetre));
  EXPECT_EQ(data.min_angle, -9000);
  EXPECT_EQ(data.max_angle, 9000);
  EXPECT_EQ(data.resolution, 50);
  EXPECT_EQ(data.range_res, 1);
  EXPECT_EQ(data.range_count, 361);
  EXPECT_EQ(data.ranges[0], 1000);
  EXPECT_EQ(data.ranges[360], 1360);
  // The whole level, 0..7 (1.5 cleared its lowest bit).
  EXPECT_EQ(data.intensity[1], 1);
  EXPECT_EQ(data.intensity[7], 7);
  EXPECT_EQ(data.intensity[8], 0);
}

TEST(SickScanConversion, RangeResSaysTheUnitWhateverTheLaserMeasuredIn) {
  // Centimetres from the laser: cm for 10 as they are, dm for 100 rounded.
  EXPECT_EQ(to_laser_data(ramp(361), lms(10, sick::Unit::centimetre)).ranges[5], 1005);
  const protocol::LaserData dm = to_laser_data(ramp(361), lms(100, sick::Unit::centimetre));
  EXPECT_EQ(dm.range_res, 100);
  EXPECT_EQ(dm.ranges[4], 100);  // 1004 cm
  EXPECT_EQ(dm.ranges[5], 101);  // 1005 cm rounds up
  // A PLS measures cm; range_res 1 reports mm.
  ScanConversion pls;
  pls.model = Model::pls;
  pls.config = default_scan_config(Model::pls);
  pls.device_unit = sick::Unit::centimetre;
  const protocol::LaserData mm = to_laser_data(ramp(361), pls);
  EXPECT_EQ(mm.range_res, 1);
  EXPECT_EQ(mm.ranges[2], 10020);
  EXPECT_EQ(mm.intensity[3], 0);  // PLS flags are not intensity
}

TEST(SickScanConversion, MillimetresBeyondTheFieldAreCapped) {
  ScanConversion pls;
  pls.model = Model::pls;
  pls.config = default_scan_config(Model::pls);
  pls.device_unit = sick::Unit::centimetre;
  sick::Scan far;
  far.values.assign(361, sick::make_value(8191));
  EXPECT_EQ(to_laser_data(far, pls).ranges[0], 65535);
}

TEST(SickScanConversion, IntensityOffReportsZeros) {
  ScanConversion conversion = lms(1, sick::Unit::millimetre);
  conversion.config.intensity = false;
  const protocol::LaserData data = to_laser_data(ramp(361), conversion);
  for (std::size_t i = 0; i < 361; ++i) ASSERT_EQ(data.intensity[i], 0) << i;
}

TEST(SickScanConversion, InvertedBeamsComeInReverseOverMirroredAngles) {
  ScanConversion conversion = lms(1, sick::Unit::millimetre);
  conversion.config.min_angle_cdeg = -9000;
  conversion.config.max_angle_cdeg = 0;  // the laser's right half
  conversion.invert = true;
  const protocol::LaserData data = to_laser_data(ramp(181), conversion);
  EXPECT_EQ(data.range_count, 181);
  EXPECT_EQ(data.min_angle, 0);  // upside down, its right half is the robot's left
  EXPECT_EQ(data.max_angle, 9000);
  EXPECT_EQ(data.ranges[0], 1180);
  EXPECT_EQ(data.ranges[180], 1000);
  EXPECT_EQ(data.intensity[0], 180 % 8);
  EXPECT_EQ(data.ranges[181], 0);  // nothing beyond range_count
}

TEST(SickScanConversion, APlsAtOneDegreeReportsEverySecondValue) {
  ScanConversion pls;
  pls.model = Model::pls;
  pls.config = default_scan_config(Model::pls);
  pls.config.resolution_cdeg = 100;
  pls.config.range_res = 10;
  pls.device_unit = sick::Unit::centimetre;
  const protocol::LaserData data = to_laser_data(ramp(361), pls);
  EXPECT_EQ(data.range_count, 181);
  EXPECT_EQ(data.resolution, 100);
  EXPECT_EQ(data.ranges[1], 1002);
  EXPECT_EQ(data.ranges[180], 1360);
}

TEST(SickScanConversion, AScanOfAnotherSizeIsAMismatch) {
  try {
    (void)to_laser_data(ramp(181), lms(1, sick::Unit::millimetre));
    ADD_FAILURE() << "expected ScanMismatch";
  } catch (const ScanMismatch& e) {
    EXPECT_NE(std::string(e.what()).find("scan of 181 values, expected 361"), std::string::npos) << e.what();
  }
}

TEST(SickScanConversion, TheFullStructGoesOnTheWire) {
  const protocol::LaserData data = to_laser_data(ramp(361), lms(1, sick::Unit::millimetre));
  EXPECT_EQ(protocol::encode(data).size(), 1213u);
}

}  // namespace sick_scan_conversion_test
}  // namespace playerkit::drivers::sick_laser
