#include "formatters.hpp"

#include <gtest/gtest.h>

#include <sstream>

#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message_json.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/power.hpp"

namespace playerkit::tools {
namespace formatters_test {

using nlohmann::json;
using protocol::Timestamp;

constexpr Timestamp kTime{1086000000, 250000};
constexpr Timestamp kDataTime{1086000000, 200000};

protocol::Message make_message(std::uint16_t interface, std::vector<std::uint8_t> payload,
                               Timestamp time = kTime, Timestamp timestamp = kDataTime) {
  protocol::Message message;
  message.header = protocol::make_header(protocol::MessageType::kData, {interface, 0}, time, timestamp);
  message.payload = std::move(payload);
  message.header.size = static_cast<std::uint32_t>(message.payload.size());
  return message;
}

protocol::Message laser_message(std::vector<std::uint16_t> ranges, Timestamp time = kTime) {
  protocol::LaserData laser;
  laser.min_angle = -9000;
  laser.max_angle = 9000;
  laser.resolution = 50;
  laser.range_res = 1;
  laser.range_count = static_cast<std::uint16_t>(ranges.size());
  for (std::size_t i = 0; i < ranges.size(); ++i) {
    laser.ranges[i] = ranges[i];
    laser.intensity[i] = static_cast<std::uint8_t>(i);
  }
  return make_message(protocol::kLaserCode, protocol::encode(laser), time);
}

protocol::Message power_message(std::uint16_t decivolts) {
  protocol::PowerData power;
  power.charge = decivolts;
  return make_message(protocol::kPowerCode, protocol::encode(power));
}

// What player-cat hands a formatter for a message.
struct Printed {
  std::ostringstream out;
  void data(Formatter& formatter, const protocol::Message& message, double shown) {
    const json j = protocol::message_to_json(message);
    formatter.data({message, j, shown});
  }
};

std::vector<FieldPath> paths(std::initializer_list<const char*> texts) {
  std::vector<FieldPath> fields;
  for (const char* text : texts) fields.push_back(FieldPath::parse(text));
  return fields;
}

TEST(TimeColumnTest, AbsoluteDeltaAndZeroBased) {
  TimeColumn absolute(TimeStyle::kAbsolute), delta(TimeStyle::kDelta), zero(TimeStyle::kZero);
  const Timestamp times[] = {{100, 0}, {100, 250000}, {101, 0}};
  const double expected_delta[] = {0.0, 0.25, 0.75};
  const double expected_zero[] = {0.0, 0.25, 1.0};
  for (int i = 0; i < 3; ++i) {
    EXPECT_DOUBLE_EQ(absolute.next(times[i]), times[i].seconds());
    EXPECT_DOUBLE_EQ(delta.next(times[i]), expected_delta[i]);
    EXPECT_DOUBLE_EQ(zero.next(times[i]), expected_zero[i]);
  }
}

TEST(FormatSecondsTest, KeepsMicroseconds) {
  EXPECT_EQ(format_seconds(Timestamp{1086000000, 250001}.seconds()), "1086000000.250001");
  EXPECT_EQ(format_seconds(0.0), "0.000000");
}

TEST(TextFormatterTest, OneLinePerMessageWithEveryField) {
  Printed printed;
  auto formatter = make_text_formatter(printed.out, {});
  printed.data(*formatter, laser_message({1000, 1500, 2000}), kTime.seconds());
  printed.data(*formatter, power_message(126), 0.5);
  EXPECT_EQ(printed.out.str(),
            "laser:0 t=1086000000.250000 intensity=[0,1,2] max_angle=9000 min_angle=-9000 range_count=3 "
            "range_res=1 ranges=[1000,1500,2000] resolution=50\n"
            "power:0 t=0.500000 charge=126\n");
}

TEST(TextFormatterTest, FieldsPrintJustThoseInTheirOrder) {
  Printed printed;
  auto formatter = make_text_formatter(printed.out, paths({"ranges.1", "range_count", "ranges"}));
  printed.data(*formatter, laser_message({1000, 1500}), 1.0);
  EXPECT_EQ(printed.out.str(), "laser:0 t=1.000000 ranges.1=1500 range_count=2 ranges=[1000,1500]\n");
}

TEST(JsonFormatterTest, OneObjectPerLineAsMessageToJson) {
  Printed printed;
  auto formatter = make_json_formatter(printed.out, {});
  const auto message = laser_message({1000, 1500});
  printed.data(*formatter, message, kTime.seconds());
  const std::string text = printed.out.str();
  ASSERT_EQ(text.back(), '\n');
  EXPECT_EQ(text.find('\n'), text.size() - 1);
  const json line = json::parse(text);
  EXPECT_EQ(line, protocol::message_to_json(message));
  EXPECT_EQ(line["device"], "laser");
  EXPECT_EQ(line["index"], 0);
  EXPECT_EQ(line["type"], "data");
  EXPECT_EQ(line["data"]["ranges"], json::array({1000, 1500}));
  // And back to the same bytes.
  EXPECT_EQ(protocol::message_from_json(line).payload, message.payload);
}

TEST(JsonFormatterTest, FieldsKeepOnlyThoseAndTheShownTimeReplacesTime) {
  Printed printed;
  auto formatter = make_json_formatter(printed.out, paths({"ranges.0", "range_count", "missing"}));
  printed.data(*formatter, laser_message({1000, 1500}), 0.25);
  const json line = json::parse(printed.out.str());
  EXPECT_EQ(line["data"], json::parse(R"({"ranges.0":1000,"range_count":2,"missing":null})"));
  EXPECT_DOUBLE_EQ(line["time"].get<double>(), 0.25);
  EXPECT_DOUBLE_EQ(line["timestamp"].get<double>(), kDataTime.seconds());
}

TEST(CsvFormatterTest, HeaderFromTheFirstMessageThenRows) {
  std::ostringstream out;
  auto formatter = make_csv_formatter({{{protocol::kLaserCode, 0}, &out}}, {});
  const auto message = laser_message({1000, 1500});
  formatter->data({message, protocol::message_to_json(message), kTime.seconds()});
  const auto second = laser_message({1001, 1501}, {1086000000, 350000});
  formatter->data({second, protocol::message_to_json(second), Timestamp{1086000000, 350000}.seconds()});
  EXPECT_EQ(out.str(),
            "time,timestamp,device,index,intensity.0,intensity.1,max_angle,min_angle,range_count,range_res,"
            "ranges.0,ranges.1,resolution\n"
            "1086000000.250000,1086000000.200000,laser,0,0,1,9000,-9000,2,1,1000,1500,50\n"
            "1086000000.350000,1086000000.200000,laser,0,0,1,9000,-9000,2,1,1001,1501,50\n");
}

TEST(CsvFormatterTest, FieldsChooseTheColumnsAndArraysFlatten) {
  std::ostringstream out;
  auto formatter = make_csv_formatter({{{protocol::kLaserCode, 0}, &out}}, paths({"range_count", "ranges"}));
  const auto message = laser_message({1000, 1500});
  formatter->data({message, protocol::message_to_json(message), 0.0});
  EXPECT_EQ(out.str(),
            "time,timestamp,device,index,range_count,ranges.0,ranges.1\n"
            "0.000000,1086000000.200000,laser,0,2,1000,1500\n");
}

TEST(CsvFormatterTest, FewerValuesLeaveEmptyCellsMoreAreAnError) {
  std::ostringstream out;
  auto formatter = make_csv_formatter({{{protocol::kLaserCode, 0}, &out}}, paths({"ranges"}));
  const auto two = laser_message({1000, 1500});
  const auto one = laser_message({1000});
  const auto three = laser_message({1000, 1500, 2000});
  formatter->data({two, protocol::message_to_json(two), 0.0});
  formatter->data({one, protocol::message_to_json(one), 1.0});
  EXPECT_EQ(out.str(),
            "time,timestamp,device,index,ranges.0,ranges.1\n"
            "0.000000,1086000000.200000,laser,0,1000,1500\n"
            "1.000000,1086000000.200000,laser,0,1000,\n");
  try {
    formatter->data({three, protocol::message_to_json(three), 2.0});
    FAIL() << "expected a CsvShapeError";
  } catch (const CsvShapeError& e) {
    EXPECT_NE(std::string(e.what()).find("laser:0: column 'ranges.2' is not in the CSV header"),
              std::string::npos)
        << e.what();
  }
}

TEST(CsvFormatterTest, EachDeviceHasItsOwnTable) {
  std::ostringstream laser_out, power_out;
  auto formatter = make_csv_formatter(
      {{{protocol::kLaserCode, 0}, &laser_out}, {{protocol::kPowerCode, 0}, &power_out}}, {});
  const auto power = power_message(126);
  const auto laser = laser_message({1000});
  formatter->data({power, protocol::message_to_json(power), 0.0});
  formatter->data({laser, protocol::message_to_json(laser), 0.0});
  EXPECT_EQ(power_out.str(), "time,timestamp,device,index,charge\n0.000000,1086000000.200000,power,0,126\n");
  EXPECT_EQ(laser_out.str().substr(0, laser_out.str().find('\n')),
            "time,timestamp,device,index,intensity.0,max_angle,min_angle,range_count,range_res,ranges.0,"
            "resolution");
}

TEST(CsvCellTest, QuotesOnlyWhatMustBeQuoted) {
  EXPECT_EQ(csv_cell(json(12)), "12");
  EXPECT_EQ(csv_cell(json(-1.5)), "-1.5");
  EXPECT_EQ(csv_cell(json(true)), "true");
  EXPECT_EQ(csv_cell(json(nullptr)), "");
  EXPECT_EQ(csv_cell(json("plain")), "plain");
  EXPECT_EQ(csv_cell(json("a,b")), "\"a,b\"");
  EXPECT_EQ(csv_cell(json("say \"hi\"")), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_cell(json("two\nlines")), "\"two\nlines\"");
}

// The log lines are lib/log's (logfile-format.md §1-3, with microsecond times,
// lib/log's compatible extension); these check that player-cat writes them so.
TEST(LogFormatterTest, HeaderThenLaserLinesAsWritelogWroteThem) {
  std::ostringstream out;
  auto formatter = make_log_formatter(out, {"localhost", 6665});
  EXPECT_EQ(out.str(), "## Player version 1.5 \n## File version 0.0.0 \n");
  const auto message = laser_message({1000, 1500, 2000});
  formatter->data({message, json::object(), 0.0});
  EXPECT_EQ(out.str(),
            "## Player version 1.5 \n## File version 0.0.0 \n"
            "1086000000.250000 localhost 6665 laser 00 1086000000.200000 "
            "-1.5708 +1.5708 +0.0087 0003 1.000  0 1.500  1 2.000  2 \n");
}

TEST(LogFormatterTest, PowerAndRoundsASyncLine) {
  std::ostringstream out;
  auto formatter = make_log_formatter(out, {"robot1", 7000});
  protocol::Message synch;
  synch.header = protocol::make_header(protocol::MessageType::kSynch, {protocol::kPlayerCode, 0},
                                       {1086000000, 300000}, {1086000000, 300000});
  formatter->synch(synch);  // no data yet: no sync line
  formatter->data({power_message(126), json::object(), 0.0});
  formatter->synch(synch);
  EXPECT_EQ(out.str(),
            "## Player version 1.5 \n## File version 0.0.0 \n"
            "1086000000.250000 robot1 7000 power 00 1086000000.200000 12.6\n"
            "1086000000.300000 robot1 7000 sync 00 1086000000.300000 \n");
}

}  // namespace formatters_test
}  // namespace playerkit::tools
