#include "log_info.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "log/log_parse_error.hpp"

namespace playerkit::plog {
namespace log_info_test {

const std::filesystem::path kRadish = std::filesystem::path(PLAYERKIT_TEST_DATA_DIR) / "radish";

LogSummary summarize(const std::filesystem::path& path, bool strict = false) {
  std::ostringstream err;
  Progress progress(err, false);
  return summarize_log(path, strict, progress);
}

TEST(LogInfo, CountsTheIntelLog) {
  const auto summary = summarize(kRadish / "intel-corrected.log.gz");
  EXPECT_EQ(summary.format, LogFormat::kCarmen);
  EXPECT_EQ(summary.streams.at("FLASER").count, 910u);
  EXPECT_EQ(summary.streams.at("ODOM").count, 14541u);
  EXPECT_EQ(summary.streams.at("PARAM").count, 2u);
  EXPECT_EQ(summary.unknown.at("NEFF"), 910u);
  EXPECT_EQ(summary.messages, 910u + 14541u);
  EXPECT_EQ(summary.malformed, 0u);
  ASSERT_TRUE(summary.start && summary.end);
  EXPECT_DOUBLE_EQ(*summary.start, 0.000246);  // the first ODOM's logger_timestamp
  ASSERT_EQ(summary.largest_gaps.size(), LogSummary::kKeptGaps);
  for (std::size_t i = 1; i < summary.largest_gaps.size(); ++i) {
    EXPECT_GE(summary.largest_gaps[i - 1].seconds, summary.largest_gaps[i].seconds);
  }
  EXPECT_TRUE(summary.streams.at("FLASER").rate().has_value());
  // `awk '($1=="ODOM"||$1=="FLASER"){t=$NF+0; if (n && t<m) b++; else m=t; n++}'` counts 2619
  // lines going back; the corrected poses written after the scans at time 0 (or garbage) go
  // back by more than 1 s, one per scan, and are interpolated (log/log_clock.hpp). What is left
  // are ODOM lines up to 1 s behind, kept as logged.
  EXPECT_EQ(summary.time_repair, log::LogTimeRepair::kInterpolated);
  EXPECT_EQ(summary.unusable_times, 910u);
  EXPECT_GT(summary.out_of_order, 0u);
  EXPECT_LT(summary.out_of_order, 2619u);
  EXPECT_LT(summary.largest_gaps[0].seconds, 60.0);
}

TEST(LogInfo, OrebroHasNoUsableTimesAndGetsSaneRates) {
  // Every scan stamped 0, the odometry with garbage (tests/data/radish/PROVENANCE.md).
  const auto summary = summarize(kRadish / "orebro-corrected.log.gz");
  EXPECT_EQ(summary.time_repair, log::LogTimeRepair::kSynthetic);
  EXPECT_EQ(summary.unusable_times, 492u);
  EXPECT_NE(summary.time_note.find("synthetic 10 Hz clock"), std::string::npos);
  EXPECT_EQ(summary.streams.at("FLASER").count, 237u);
  EXPECT_EQ(summary.streams.at("ODOM").count, 255u);
  EXPECT_EQ(summary.out_of_order, 0u);
  ASSERT_TRUE(summary.start && summary.end);
  EXPECT_DOUBLE_EQ(*summary.end - *summary.start, 491 / log::LogClock::kSyntheticRateHz);
  for (const char* stream : {"FLASER", "ODOM"}) {
    const auto rate = summary.streams.at(stream).rate();
    ASSERT_TRUE(rate) << stream;
    EXPECT_GT(*rate, 0.0) << stream;
    EXPECT_LE(*rate, log::LogClock::kSyntheticRateHz) << stream;
  }
}

TEST(LogInfo, ParamLinesHaveNoRate) {
  // Freiburg 079's PARAM lines are stamped at the epoch, its data from 0: not a stream.
  const auto summary = summarize(kRadish / "freiburg-079-corrected.log.gz");
  EXPECT_EQ(summary.streams.at("PARAM").count, 187u);
  EXPECT_FALSE(summary.streams.at("PARAM").rate());
}

TEST(LogInfo, PlayerLogDevicesGapsRatesAndMalformedLines) {
  const auto path = std::filesystem::path(::testing::TempDir()) / "info.log";
  std::ofstream(path) << "## Player version 1.5 \n## File version 0.0.0 \n"
                         "10.000 h 6665 position 00 10.000 +0.000 +0.000 +0.000 +0.000 +0.000 +0.000 0\n"
                         "10.500 h 6665 position 00 10.500 +1.000 +0.000 +0.000 +0.000 +0.000 +0.000 0\n"
                         "10.500 h 6665 sync 00 10.500 \n"
                         "this line is broken\n"
                         "13.500 h 6665 position 00 13.500 +2.000 +0.000 +0.000 +0.000 +0.000 +0.000 0\n"
                         "14.000 h 6665 truth 00 14.000 +1.000 +2.000 +0.500\n";
  const auto summary = summarize(path);
  EXPECT_EQ(summary.format, LogFormat::kPlayer);
  EXPECT_EQ(summary.version, "0.0.0");
  EXPECT_EQ(summary.streams.at("position:0").count, 3u);
  EXPECT_EQ(summary.streams.at("truth:0").count, 1u);
  EXPECT_EQ(summary.streams.at("sync").count, 1u);
  EXPECT_EQ(summary.messages, 4u);
  EXPECT_DOUBLE_EQ(*summary.streams.at("position:0").rate(), 2.0 / 3.5);
  EXPECT_FALSE(summary.streams.at("truth:0").rate().has_value());
  ASSERT_EQ(summary.largest_gaps.size(), 3u);
  EXPECT_DOUBLE_EQ(summary.largest_gaps[0].seconds, 3.0);
  EXPECT_DOUBLE_EQ(summary.largest_gaps[0].after, 0.5);
  EXPECT_EQ(summary.out_of_order, 0u);
  EXPECT_EQ(summary.malformed, 1u);
  ASSERT_EQ(summary.malformed_texts.size(), 1u);
  EXPECT_EQ(summary.malformed_texts[0].rfind(path.string() + ":6:", 0), 0u) << summary.malformed_texts[0];
  EXPECT_THROW(summarize(path, true), log::LogParseError);

  const auto json = summary_json(summary);
  EXPECT_EQ(json["format"], "player");
  EXPECT_EQ(json["devices"]["position:0"]["count"], 3);
  EXPECT_EQ(json["malformed"], 1);
  std::ostringstream text;
  print_summary(summary, text);
  EXPECT_NE(text.str().find("position:0"), std::string::npos);
  EXPECT_NE(text.str().find("malformed: 1"), std::string::npos);
}

}  // namespace log_info_test
}  // namespace playerkit::plog
