#include "log_convert.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <optional>
#include <fstream>
#include <nlohmann/json.hpp>
#include <iterator>
#include <sstream>
#include <variant>

#include "log/carmen_log_reader.hpp"
#include "log/log_clock_reader.hpp"
#include "log/log_input.hpp"
#include "log/text_log_reader.hpp"
#include "log_info.hpp"
#include "protocol/interfaces.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::plog {
namespace log_convert_test {

const std::filesystem::path kIntel =
    std::filesystem::path(PLAYERKIT_TEST_DATA_DIR) / "radish" / "intel-corrected.log.gz";

std::string temp(const std::string& name) { return (std::filesystem::path(::testing::TempDir()) / name).string(); }

ConvertOptions convert_options(const std::string& input, const std::string& output,
                               std::optional<ConvertTarget> to = std::nullopt,
                               std::vector<protocol::DeviceAddress> devices = {}) {
  ConvertOptions options;
  options.input = input;
  options.output = output;
  options.to = to;
  options.devices = std::move(devices);
  return options;
}

CutOptions cut_options(const std::string& input, std::optional<double> start, std::optional<double> end,
                       std::vector<protocol::DeviceAddress> devices = {}) {
  CutOptions options;
  options.input = input;
  options.output = std::string("-");  // (GCC 12 warns falsely on assigning the literal)
  options.start = start;
  options.end = end;
  options.devices = std::move(devices);
  return options;
}

std::string convert(ConvertOptions options) {
  std::ostringstream out, err;
  Progress progress(err, false);
  run_convert(options, out, err, progress);
  return out.str();
}

std::map<std::string, std::size_t> counts(const std::string& path) {
  std::ostringstream err;
  Progress progress(err, false);
  std::map<std::string, std::size_t> result;
  for (const auto& [name, stream] : summarize_log(path, true, progress).streams) result[name] = stream.count;
  return result;
}

TEST(Convert, CarmenToPlayerAndBackKeepsEveryScan) {
  convert(convert_options(kIntel.string(), temp("intel.player.log")));
  EXPECT_EQ(counts(temp("intel.player.log")),
            (std::map<std::string, std::size_t>{{"laser:0", 910}, {"position:0", 910 + 14541}, {"truth:0", 910}}));
  convert(convert_options(temp("intel.player.log"), temp("intel.carmen.log")));
  EXPECT_EQ(counts(temp("intel.carmen.log")),
            (std::map<std::string, std::size_t>{{"FLASER", 910}, {"ODOM", 14541}}));

  // The ranges of the first scan, to the file's precision (1 cm with 81.83 m readings).
  const auto first_scan = [](const std::string& path) {
    auto in = log::open_log_input(path);
    log::CarmenLogReader reader(*in, path);
    while (auto record = reader.next()) {
      if (auto* scan = std::get_if<log::CarmenLaser>(&*record)) return scan->ranges;
    }
    return std::vector<double>{};
  };
  const auto original = first_scan(kIntel.string());
  const auto back = first_scan(temp("intel.carmen.log"));
  ASSERT_EQ(back.size(), 180u);
  ASSERT_EQ(original.size(), back.size());
  for (std::size_t i = 0; i < back.size(); ++i) EXPECT_NEAR(back[i], original[i], 0.0051) << i;
}

TEST(Convert, JsonLinesAndCsvOfOneDevice) {
  const auto jsonl = convert(convert_options(kIntel.string(), "-", ConvertTarget::kJsonl, {{protocol::kLaserCode, 0}}));
  std::istringstream lines(jsonl);
  std::string line;
  std::size_t scans = 0;
  while (std::getline(lines, line)) {
    const auto json = nlohmann::json::parse(line);
    EXPECT_EQ(json["device"], "laser");
    EXPECT_EQ(json["data"]["range_count"], 180);
    ++scans;
  }
  EXPECT_EQ(scans, 910u);

  const auto csv = convert(convert_options(kIntel.string(), "-", ConvertTarget::kCsv, {{protocol::kPositionCode, 0}}));
  EXPECT_EQ(csv.rfind("time,timestamp,device,index,", 0), 0u) << csv.substr(0, 200);
  EXPECT_EQ(static_cast<std::size_t>(std::count(csv.begin(), csv.end(), '\n')), 1u + 910u + 14541u);
  EXPECT_THROW(convert(convert_options(kIntel.string(), "-", ConvertTarget::kCsv)), UsageError);
  EXPECT_THROW(parse_convert_target("xml"), UsageError);
}

TEST(Cut, KeepsTheWindowAndTheDevicesByteForByte) {
  const std::string header = "## Player version 1.5 \n## File version 0.0.0 \n";
  const std::string lines[] = {
      "100.000 h 6665 position 00 100.000 +0.000 +0.000 +0.000 +0.000 +0.000 +0.000 0",
      "101.000 h 6665 truth 00 101.000 +1.000 +2.000 +0.500",
      "101.000 h 6665 sync 00 101.000 ",
      "102.000 h 6665 position 00 102.000 +2.000 +0.000 +0.000 +0.000 +0.000 +0.000 0",
      "103.500 h 6665 position 00 103.500 +3.000 +0.000 +0.000 +0.000 +0.000 +0.000 0",
  };
  {
    std::ofstream file(temp("cut-in.log"));
    file << header;
    for (const auto& l : lines) file << l << "\n";
  }
  std::ostringstream out, err;
  Progress progress(err, false);
  run_cut(cut_options(temp("cut-in.log"), 1.0, 2.0), out, err, progress);
  EXPECT_EQ(out.str(), header + lines[1] + "\n" + lines[2] + "\n" + lines[3] + "\n");
  out.str("");
  run_cut(cut_options(temp("cut-in.log"), 1.0, std::nullopt, {{protocol::kPositionCode, 0}}), out, err, progress);
  EXPECT_EQ(out.str(), header + lines[2] + "\n" + lines[3] + "\n" + lines[4] + "\n");
  EXPECT_THROW(run_cut(cut_options(kIntel.string(), std::nullopt, std::nullopt), out, err, progress), std::runtime_error);
}

TEST(Cut, ALogWithoutUsableTimesIsCutInFileOrderOnTheSyntheticClock) {
  // Every line stamped 0 (as Radish's Orebro log): 1.5 would keep all or
  // nothing; the window is taken on the 10 Hz clock every reader uses.
  std::string text = "## Player version 1.5 \n## File version 0.0.0 \n";
  std::vector<std::string> lines;
  for (int i = 0; i < 30; ++i) {
    lines.push_back("0000000000.000 h 6665 position 00 0000000000.000 +" + std::to_string(i) +
                    ".000 +0.000 +0.000 +0.000 +0.000 +0.000 0");
    text += lines.back() + "\n";
  }
  testing::ScratchDirectory scratch("log_convert_test");
  const auto input = scratch.write("zero.log", text);
  std::vector<std::string> warnings;
  const auto previous = log::set_log_clock_warning_handler([&](const std::string& w) { warnings.push_back(w); });
  std::ostringstream out, err;
  Progress progress(err, false);
  run_cut(cut_options(input.string(), 0.95, 2.05), out, err, progress);
  log::set_log_clock_warning_handler(previous);
  std::string expected = "## Player version 1.5 \n## File version 0.0.0 \n";
  for (int i = 10; i <= 20; ++i) expected += lines[static_cast<std::size_t>(i)] + "\n";
  EXPECT_EQ(out.str(), expected);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("synthetic 10 Hz clock"), std::string::npos) << warnings[0];
}

std::vector<std::string> directory_entries(const std::filesystem::path& directory) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST(Convert, ADamagedGzipLeavesNoOutputAndAnOlderFileWhole) {
  testing::ScratchDirectory scratch("log_convert_test");
  std::ifstream source(kIntel, std::ios::binary);
  const std::string bytes{std::istreambuf_iterator<char>(source), std::istreambuf_iterator<char>()};
  const auto damaged = scratch.write("cut.log.gz", bytes.substr(0, bytes.size() / 3));
  const auto older = scratch.write("older.log", "an older output\n");
  for (const auto& output : {scratch.file("new.log"), older}) {
    try {
      convert(convert_options(damaged.string(), output.string(), ConvertTarget::kPlayer));
      FAIL() << "converted a damaged file";
    } catch (const std::runtime_error& e) {
      const std::string text = e.what();
      EXPECT_TRUE(text.starts_with(damaged.string() + ": gzip data cut short: the file ends at byte " +
                                   std::to_string(bytes.size() / 3) + ", in line "))
          << text;
    }
  }
  EXPECT_EQ(directory_entries(scratch.path()), (std::vector<std::string>{"cut.log.gz", "older.log"}));
  std::ifstream kept(older);
  std::string line;
  std::getline(kept, line);
  EXPECT_EQ(line, "an older output");
}

TEST(Cut, WritingOverTheInputIsAUsageErrorAndTouchesNothing) {
  testing::ScratchDirectory scratch("log_convert_test");
  const std::string log = "## Player version 1.5 \n100.000 h 6665 truth 00 100.000 +1.000 +2.000 +0.500\n";
  const auto input = scratch.write("a.log", log);
  std::filesystem::create_symlink(input, scratch.file("link.log"));
  std::ostringstream out, err;
  Progress progress(err, false);
  for (const auto& spelling : {(scratch.path() / "." / "a.log").string(), scratch.file("link.log").string()}) {
    CutOptions options = cut_options(input.string(), std::nullopt, std::nullopt);
    options.output = spelling;
    EXPECT_THROW(run_cut(options, out, err, progress), UsageError) << spelling;
    EXPECT_THROW(convert(convert_options(input.string(), spelling, ConvertTarget::kCarmen)), UsageError);
  }
  std::ifstream kept(input, std::ios::binary);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(kept), std::istreambuf_iterator<char>()), log);
}

}  // namespace log_convert_test
}  // namespace playerkit::plog
