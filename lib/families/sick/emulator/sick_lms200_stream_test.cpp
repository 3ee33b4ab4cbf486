// The LMS 200 emulator's scans: golden telegrams, variants, units, subranges,
// ranges against a hand-computed room, reflectors, noise, pacing, and how the
// stream stops.

#include "families/sick/emulator/sick_lms200_emulator.hpp"

#include "families/sick/emulator/sick_test_host.hpp"
#include "families/sick/emulator/sick_test_room.hpp"
#include "families/sick/protocol/replies.hpp"
#include "families/sick/protocol/test_bytes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace playerkit::emulators {
namespace sick_lms200_stream_test {

using namespace std::chrono_literals;
using testing::Received;
using testing::TestHost;
using hardware::sick::testing::bytes;
namespace sick = hardware::sick;

std::vector<std::uint8_t> repeated(const char* pair, int times) {
  std::vector<std::uint8_t> out;
  const auto one = bytes(pair);
  for (int i = 0; i < times; ++i) out.insert(out.end(), one.begin(), one.end());
  return out;
}

std::vector<std::uint8_t> concat(std::initializer_list<std::vector<std::uint8_t>> parts) {
  std::vector<std::uint8_t> out;
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

// What the reference driver does before streaming: installation mode, the
// variant, the configuration (measuring mode and unit).
void set_up(TestHost& host, sick::Variant variant, sick::MeasuringMode mode, sick::Unit unit) {
  ASSERT_EQ(host.ask(sick::InstallationModeRequest{"SICK_LMS"}).code, 0xA0);
  ASSERT_TRUE(sick::parse_variant_reply(host.ask(sick::SetVariantRequest{variant})).accepted);
  sick::SetConfigRequest request{sick::parse_config_reply(host.ask(sick::GetConfigRequest{})).config};
  request.config.set_measuring_mode(mode);
  request.config.set_unit(unit);
  ASSERT_TRUE(sick::parse_set_config_reply(host.ask(request)).accepted);
}

// Streams with `request` for `span` and returns the scans.
std::vector<sick::Scan> stream(TestHost& host, const sick::Request& request, Duration span) {
  EXPECT_EQ(host.ask(request), (sick::Reply{0xA0, {0x00}, 0x10}));
  host.wait(span);
  return testing::scans_of(host.drain());
}

double beam_angle(const sick::Variant& variant, std::size_t index) {
  return variant.first_angle_rad() + static_cast<double>(index) * variant.step_rad();
}

TEST(SickLms200Stream, B0IsTheSheetsGoldenTelegram) {
  SickLms200Emulator device({.range_without_map_m = 1.0});
  TestHost host(device, 9600);
  host.ask(sick::StreamAllRequest{});
  host.wait(2s);
  const auto telegrams = host.drain();
  ASSERT_FALSE(telegrams.empty());
  EXPECT_EQ(telegrams[0].bytes,
            concat({bytes("02 80 D6 02 B0 69 41"), repeated("E8 03", 361), bytes("10 55 F1")}));
}

TEST(SickLms200Stream, B7IsTheSheetsGoldenTelegram) {
  SickLms200Emulator device({.range_without_map_m = 2.0});
  TestHost host(device, 9600);
  ASSERT_TRUE(sick::parse_variant_reply(host.ask(sick::SetVariantRequest{{180, 100}})).accepted);
  host.ask(sick::StreamSubrangeRequest{{1, 181}});
  host.wait(2s);
  const auto telegrams = host.drain();
  ASSERT_FALSE(telegrams.empty());
  EXPECT_EQ(telegrams[0].bytes, concat({bytes("02 80 72 01 B7 01 00 B5 00 B5 40"),
                                        repeated("D0 07", 181), bytes("10 05 C2")}));
}

TEST(SickLms200Stream, EveryVariantInEveryUnitMatchesTheRoom) {
  const grid::OccupancyGrid room = testing::box_room();
  const geometry::Pose2 pose{1.0, 1.2, 0.4};
  for (const sick::Unit unit : {sick::Unit::millimetre, sick::Unit::centimetre}) {
    const double steps_per_metre = unit == sick::Unit::millimetre ? 1000.0 : 100.0;
    for (const sick::Variant& variant : sick::kLms200Variants) {
      SCOPED_TRACE(::testing::Message() << variant.width_deg << " deg / " << variant.resolution_cdeg
                                        << " cdeg, unit " << static_cast<int>(unit));
      SickLms200Emulator device({.map = &room, .pose = pose, .power_up_baud = 500000});
      TestHost host(device, 500000);
      set_up(host, variant, sick::MeasuringMode::reflector_levels, unit);
      const auto scans = stream(host, sick::StreamAllRequest{}, 100ms);
      ASSERT_FALSE(scans.empty());
      const sick::Scan& scan = scans.front();
      EXPECT_EQ(scan.unit, unit);
      ASSERT_EQ(scan.values.size(), static_cast<std::size_t>(variant.value_count()));
      for (std::size_t i = 0; i < scan.values.size(); ++i) {
        const double expected =
            steps_per_metre * testing::room_range(pose.translation(), pose.yaw + beam_angle(variant, i));
        EXPECT_NEAR(sick::distance_of(scan.values[i]), expected, 1.0) << "value " << i;
      }
    }
  }
}

TEST(SickLms200Stream, BeamsRunCounterClockwiseFromTheRight) {
  const grid::OccupancyGrid room = testing::box_room();
  // Facing +y from (1.0, 1.2): the first beam looks along +x (right), the
  // middle one along +y, the last along -x.
  SickLms200Emulator device({.map = &room, .pose = {1.0, 1.2, std::numbers::pi / 2}});
  TestHost host(device);
  const auto scans = stream(host, sick::StreamAllRequest{}, 1s);
  ASSERT_FALSE(scans.empty());
  const auto& values = scans.front().values;
  EXPECT_EQ(sick::distance_of(values.front()), 1950);  // to x = 2.95
  EXPECT_EQ(sick::distance_of(values[180]), 1750);     // to y = 2.95
  EXPECT_EQ(sick::distance_of(values.back()), 950);    // to x = 0.05
}

TEST(SickLms200Stream, NothingInRangeReadsTheMaximum) {
  // No map: all the unit encodes, 8191 steps.
  for (const sick::Unit unit : {sick::Unit::millimetre, sick::Unit::centimetre}) {
    SickLms200Emulator device({.power_up_baud = 500000});
    TestHost host(device, 500000);
    set_up(host, {180, 100}, sick::MeasuringMode::fields_and_dazzle, unit);
    EXPECT_DOUBLE_EQ(device.max_range_m(), unit == sick::Unit::millimetre ? 8.191 : 81.91);
    const auto scans = stream(host, sick::StreamAllRequest{}, 100ms);
    ASSERT_FALSE(scans.empty());
    for (const std::uint16_t value : scans.front().values) EXPECT_EQ(value, 8191);
  }
  // A shorter max range, in a room whose walls are all further than 1 m.
  const grid::OccupancyGrid room = testing::box_room();
  SickLms200Emulator device({.map = &room, .pose = {1.5, 1.5, 0.0}, .max_range_m = 1.0});
  TestHost host(device);
  const auto scans = stream(host, sick::StreamAllRequest{}, 1s);
  ASSERT_FALSE(scans.empty());
  for (const std::uint16_t value : scans.front().values) EXPECT_EQ(value, 1000);
}

TEST(SickLms200Stream, SubrangeIsTheSameValuesAsTheFullScan) {
  const grid::OccupancyGrid room = testing::box_room();
  SickLms200Emulator device({.map = &room, .pose = {1.1, 1.7, -0.3}, .power_up_baud = 500000});
  TestHost host(device, 500000);
  set_up(host, {100, 25}, sick::MeasuringMode::fields_and_dazzle, sick::Unit::millimetre);
  const auto full = stream(host, sick::StreamAllRequest{}, 100ms);
  const auto part = stream(host, sick::StreamSubrangeRequest{{100, 120}}, 100ms);
  ASSERT_FALSE(full.empty());
  ASSERT_FALSE(part.empty());
  EXPECT_EQ(full.front().values.size(), 401u);
  const sick::Scan& scan = part.front();
  EXPECT_EQ(scan.subrange, (sick::Subrange{100, 120}));
  ASSERT_EQ(scan.values.size(), 21u);
  for (std::size_t i = 0; i < 21; ++i) EXPECT_EQ(scan.values[i], full.front().values[99 + i]) << i;
}

TEST(SickLms200Stream, ReflectorLevelsOnlyInMeasuringMode01) {
  const grid::OccupancyGrid room = testing::box_room();
  // Tape on the inner face of the right wall, y 1.0..1.4; the laser looks
  // at it from (1.5, 1.2): beams within atan(0.2 / 1.45) = 7.85 deg of ahead.
  const SickEmulatorOptions options{.map = &room,
                                    .pose = {1.5, 1.2, 0.0},
                                    .reflectors = {{{2.95, 1.0}, {2.95, 1.4}, 5}}};
  for (const auto mode : {sick::MeasuringMode::reflector_levels,
                          sick::MeasuringMode::fields_and_dazzle}) {
    SickLms200Emulator device(options);
    TestHost host(device);
    set_up(host, {180, 50}, mode, sick::Unit::millimetre);
    const auto scans = stream(host, sick::StreamAllRequest{}, 1s);
    ASSERT_FALSE(scans.empty());
    const auto& values = scans.front().values;
    const std::uint8_t tape = mode == sick::MeasuringMode::reflector_levels ? 5 : 0;
    for (const std::size_t on_tape : {165u, 170u, 180u, 195u}) {
      EXPECT_EQ(sick::flags_of(values[on_tape]), tape) << on_tape;
    }
    for (const std::size_t off_tape : {0u, 150u, 160u, 200u, 360u}) {
      EXPECT_EQ(sick::flags_of(values[off_tape]), 0) << off_tape;
    }
    // The tape lies on the wall: the range is the wall's.
    EXPECT_EQ(sick::distance_of(values[180]), 1450);
  }
}

TEST(SickLms200Stream, ReflectorsAreSeenWithoutAMap) {
  SickLms200Emulator device({.reflectors = {{{1.0, -0.5}, {1.0, 0.5}, 3}}});
  TestHost host(device);
  set_up(host, {180, 50}, sick::MeasuringMode::reflector_levels, sick::Unit::millimetre);
  const auto scans = stream(host, sick::StreamAllRequest{}, 1s);
  ASSERT_FALSE(scans.empty());
  EXPECT_EQ(scans.front().values[180], sick::make_value(1000, 3));
  EXPECT_EQ(scans.front().values[0], sick::make_value(8191, 0));
}

TEST(SickLms200Stream, FollowsAMovingPose) {
  const grid::OccupancyGrid room = testing::box_room();
  geometry::Pose2 pose{1.0, 1.2, 0.0};
  SickLms200Emulator device({.map = &room, .pose_source = [&pose] { return pose; }});
  TestHost host(device, 9600);
  host.ask(sick::StreamAllRequest{});
  host.wait(1s);
  pose.x = 2.0;
  host.wait(1s);
  const auto scans = testing::scans_of(host.drain());
  ASSERT_GE(scans.size(), 2u);
  EXPECT_EQ(sick::distance_of(scans.front().values[180]), 1950);
  EXPECT_EQ(sick::distance_of(scans.back().values[180]), 950);
}

TEST(SickLms200Stream, NoiseIsGaussianSeededAndOnlyOnReturns) {
  const auto noisy_values = [](std::uint64_t seed) {
    SickLms200Emulator device({.range_without_map_m = 2.0,
                               .range_noise_sigma_m = 0.02,
                               .noise_seed = seed,
                               .power_up_baud = 500000});
    TestHost host(device, 500000);
    std::vector<double> values;
    for (const sick::Scan& scan : stream(host, sick::StreamAllRequest{}, 300ms)) {
      for (const std::uint16_t value : scan.values) values.push_back(sick::distance_of(value));
    }
    return values;
  };
  const auto values = noisy_values(7);
  ASSERT_GE(values.size(), 361u * 15);
  double sum = 0.0;
  for (const double value : values) sum += value;
  const double mean = sum / static_cast<double>(values.size());
  double squares = 0.0;
  for (const double value : values) squares += (value - mean) * (value - mean);
  const double sigma = std::sqrt(squares / static_cast<double>(values.size() - 1));
  // Standard error of the mean ~0.3 mm; of sigma ~0.2 mm (plus rounding to mm).
  EXPECT_NEAR(mean, 2000.0, 1.5);
  EXPECT_NEAR(sigma, 20.0, 1.5);
  EXPECT_EQ(noisy_values(7), values);
  EXPECT_NE(noisy_values(8), values);

  // No return, no noise: the maximum stays exact.
  SickLms200Emulator device({.range_noise_sigma_m = 0.5});
  TestHost host(device);
  const auto scans = stream(host, sick::StreamAllRequest{}, 1s);
  ASSERT_FALSE(scans.empty());
  for (const std::uint16_t value : scans.front().values) EXPECT_EQ(value, 8191);
}

// Emission times of the stream's telegrams and their sizes.
std::vector<Received> stream_for(TestHost& host, const sick::Request& request, Duration span) {
  EXPECT_EQ(host.ask(request).code, 0xA0);
  host.wait(span);
  return host.drain();
}

void expect_line_keeps_up(const SickLaserEmulator& device, const std::vector<Received>& telegrams) {
  for (std::size_t i = 1; i < telegrams.size(); ++i) {
    EXPECT_GE(telegrams[i].at - telegrams[i - 1].at, device.line_time(telegrams[i - 1].bytes.size()))
        << "telegram " << i;
  }
}

std::size_t count_within(const std::vector<Received>& telegrams, Duration from, Duration span) {
  std::size_t count = 0;
  for (const Received& telegram : telegrams) count += telegram.at >= from && telegram.at < from + span;
  return count;
}

TEST(SickLms200Stream, PacedByTheLineAt38400) {
  SickLms200Emulator device({.power_up_baud = 38400});
  TestHost host(device, 38400);
  const auto telegrams = stream_for(host, sick::StreamAllRequest{}, 3s);
  ASSERT_GE(telegrams.size(), 2u);
  expect_line_keeps_up(device, telegrams);
  // 732 bytes of 10 bits: 190.6 ms each, so 5.2 scans a second.
  EXPECT_EQ(device.scan_period(), device.line_time(732));
  EXPECT_EQ(device.line_time(732), Duration(190'625'000));
  const std::size_t in_a_second = count_within(telegrams, telegrams.front().at, 1s);
  EXPECT_GE(in_a_second, 5u);
  EXPECT_LE(in_a_second, 6u);
}

TEST(SickLms200Stream, PacedByLineAndMirrorAt500000) {
  SickLms200Emulator device({.power_up_baud = 500000});
  TestHost host(device, 500000);
  // 361 values: 732 bytes take 14.64 ms at 500000 baud, longer than the
  // mirror's 13.33 ms, so 68 scans a second. (75 scans of 361 values would
  // need 75 * 732 * 10 = 549,000 bit/s.)
  auto telegrams = stream_for(host, sick::StreamAllRequest{}, 2s);
  expect_line_keeps_up(device, telegrams);
  EXPECT_EQ(device.scan_period(), Duration(14'640'000));
  EXPECT_GE(count_within(telegrams, telegrams.front().at, 1s), 68u);

  // 181 values (1 deg): the line would carry 134 a second, the mirror turns
  // 75 times.
  ASSERT_TRUE(sick::parse_variant_reply(host.ask(sick::SetVariantRequest{{180, 100}})).accepted);
  telegrams = stream_for(host, sick::StreamAllRequest{}, 2s);
  expect_line_keeps_up(device, telegrams);
  EXPECT_EQ(device.scan_period(), Duration(13'333'333));
  EXPECT_GE(count_within(telegrams, telegrams.front().at, 1s), 75u);
  EXPECT_LE(count_within(telegrams, telegrams.front().at, 1s), 76u);
}

TEST(SickLms200Stream, SlowerAtLowerRatesAndNarrowerSubranges) {
  SickLms200Emulator device;
  TestHost host(device, 9600);
  auto telegrams = stream_for(host, sick::StreamAllRequest{}, 5s);
  EXPECT_EQ(device.scan_period(), device.line_time(732));  // 762.5 ms
  // The first after the A0 and one rotation (24 ms), then every 762.5 ms.
  EXPECT_EQ(telegrams.size(), 7u);
  EXPECT_EQ(telegrams[1].at - telegrams[0].at, Duration(762'500'000));
  expect_line_keeps_up(device, telegrams);
  telegrams = stream_for(host, sick::StreamSubrangeRequest{{170, 190}}, 1s);
  EXPECT_EQ(device.scan_period(), device.line_time(sick::subrange_scan_telegram_size(21)));
  expect_line_keeps_up(device, telegrams);
  EXPECT_GE(telegrams.size(), 15u);
}

TEST(SickLms200Stream, AnyRequestStopsTheStreamBeforeItsAnswer) {
  SickLms200Emulator device({.power_up_baud = 38400});
  TestHost host(device, 38400);
  host.ask(sick::StreamAllRequest{});
  host.wait(1s);
  EXPECT_GT(device.scans_sent(), 0u);
  // The host flushes, asks, and the next telegram is the answer.
  EXPECT_EQ(host.ask(sick::GetTypeRequest{}).code, 0xBA);
  EXPECT_EQ(device.mode(), SickLaserEmulator::Mode::idle);
  const std::size_t writes = host.writes().size();
  host.wait(5s);
  EXPECT_TRUE(host.silent_since(writes));
  EXPECT_EQ(device.next_deadline(), Duration::max());

  // T1 stops it too (what a restarted driver relies on).
  host.ask(sick::StreamAllRequest{});
  host.wait(1s);
  EXPECT_EQ(host.ask(sick::InstallationModeRequest{"SICK_LMS"}).code, 0xA0);
  const std::size_t after_t1 = host.writes().size();
  host.wait(5s);
  EXPECT_TRUE(host.silent_since(after_t1));
}

TEST(SickLms200Stream, ARequestArrivingHoldsTheStream) {
  // At 500000 baud a scan is due every 14.6 ms, several while the request waits.
  SickLms200Emulator device({.power_up_baud = 500000});
  TestHost host(device, 500000);
  host.ask(sick::StreamAllRequest{});
  host.wait(1s);
  // The first bytes of a request (after the host's flush): no scan may slip
  // in before its answer.
  host.drain();
  const auto t3 = sick::encode_request(sick::GetTypeRequest{});
  host.write({t3.begin(), t3.begin() + 2});
  const std::size_t writes = host.writes().size();
  host.wait(SickLaserEmulator::kInterByteTimeout - 1ms);
  EXPECT_TRUE(host.silent_since(writes));
  host.write({t3.begin() + 2, t3.end()});
  EXPECT_EQ(host.next_reply()->code, 0xBA);
}

TEST(SickLms200Stream, LineNoiseAndBadTelegramsDoNotStopTheStream) {
  SickLms200Emulator device({.power_up_baud = 38400});
  TestHost host(device, 38400);
  host.ask(sick::StreamAllRequest{});
  host.wait(500ms);
  // The host at another speed: noise.
  host.set_baud(9600);
  host.write(sick::encode_request(sick::GetTypeRequest{}));
  host.set_baud(38400);
  auto corrupt = sick::encode_request(sick::GetTypeRequest{});
  corrupt.back() ^= 0x01;
  host.write(corrupt);  // NAK, ignored
  EXPECT_EQ(host.writes().back().second.bytes, std::vector<std::uint8_t>{0x15});
  const std::uint64_t before = device.scans_sent();
  host.wait(1s);
  EXPECT_GE(device.scans_sent(), before + 5);
  EXPECT_EQ(device.mode(), SickLaserEmulator::Mode::streaming_all);
}

TEST(SickLms200Stream, KeepsStreamingAndItsStateWhenTheHostGoesAway) {
  SickLms200Emulator device({.power_up_baud = 9600});
  TestHost host(device, 9600);
  set_up(host, {180, 100}, sick::MeasuringMode::reflector_levels, sick::Unit::centimetre);
  host.ask(sick::BaudRateRequest{38400});
  host.set_baud(38400);
  host.ask(sick::StreamSubrangeRequest{{1, 181}});
  host.wait(1s);
  device.host_disconnected(host.now());
  const std::uint64_t before = device.scans_sent();
  host.wait(1s);
  EXPECT_GT(device.scans_sent(), before);
  EXPECT_EQ(device.baud(), 38400);
  EXPECT_EQ(device.variant(), (sick::Variant{180, 100}));
  EXPECT_EQ(device.unit(), sick::Unit::centimetre);
  EXPECT_EQ(device.mode(), SickLaserEmulator::Mode::streaming_subrange);
  // The next driver's T1 at 38400 stops the stream.
  host.drain();
  EXPECT_EQ(host.ask(sick::InstallationModeRequest{"SICK_LMS"}).code, 0xA0);
}

}  // namespace sick_lms200_stream_test
}  // namespace playerkit::emulators
