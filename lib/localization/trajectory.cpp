#include "localization/trajectory.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>

#include "log/log_input.hpp"
#include "text/line_reader.hpp"

namespace playerkit::localization {
namespace {

std::string_view trimmed(std::string_view text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

std::vector<std::string_view> split_csv(std::string_view line) {
  std::vector<std::string_view> fields;
  while (true) {
    const auto comma = line.find(',');
    fields.push_back(trimmed(line.substr(0, comma)));
    if (comma == std::string_view::npos) break;
    line.remove_prefix(comma + 1);
  }
  return fields;
}

std::optional<double> finite_number(std::string_view text) {
  if (text.size() > 1 && text.front() == '+') text.remove_prefix(1);
  double value = 0;
  const auto parsed = std::from_chars(text.data(), text.data() + text.size(), value);
  if (text.empty() || parsed.ec != std::errc{} || parsed.ptr != text.data() + text.size() ||
      !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

constexpr std::array<std::string_view, 4> kColumns{"time", "x", "y", "yaw"};
constexpr std::array<std::string_view, 4> kSpreadColumns{"std_x", "std_y", "std_yaw", "cov_xy"};

std::optional<std::size_t> column_named(const std::vector<std::string_view>& header, std::string_view name) {
  const auto at = std::find(header.begin(), header.end(), name);
  if (at == header.end()) return std::nullopt;
  return static_cast<std::size_t>(at - header.begin());
}

}  // namespace

Trajectory read_trajectory_csv(std::istream& in, std::string_view name) {
  const auto fail = [&](int line, const std::string& message) -> std::runtime_error {
    return std::runtime_error(std::string(name) + ":" + std::to_string(line) + ": " + message);
  };
  Trajectory trajectory;
  std::optional<std::array<std::size_t, 4>> column_of;  // time, x, y, yaw
  std::array<std::optional<std::size_t>, 4> spread_column_of;  // std_x, std_y, std_yaw, cov_xy
  bool has_spread = false;
  std::size_t needed_fields = 0;
  std::string line;
  int number = 0;
  while (text::read_line(in, line, name, number + 1)) {
    ++number;
    const auto content = trimmed(line);
    if (content.empty() || content.front() == '#') continue;
    const auto fields = split_csv(content);
    if (!column_of) {
      std::array<std::size_t, 4> found{};
      for (std::size_t c = 0; c < kColumns.size(); ++c) {
        std::size_t at = 0;
        while (at < fields.size() && fields[at] != kColumns[c]) ++at;
        if (at == fields.size()) {
          throw fail(number, std::string("the header has no column '") + std::string(kColumns[c]) +
                                 "' (it needs time, x, y, yaw)");
        }
        found[c] = at;
        needed_fields = std::max(needed_fields, at + 1);
      }
      column_of = found;
      for (std::size_t c = 0; c < kSpreadColumns.size(); ++c) spread_column_of[c] = column_named(fields, kSpreadColumns[c]);
      has_spread = spread_column_of[0] && spread_column_of[1] && spread_column_of[2];
      if (has_spread) {
        for (const auto& at : spread_column_of) {
          if (at) needed_fields = std::max(needed_fields, *at + 1);
        }
      }
      continue;
    }
    if (fields.size() < needed_fields) {
      throw fail(number, std::to_string(fields.size()) + " fields, the header needs " + std::to_string(needed_fields));
    }
    std::array<double, 4> values{};
    for (std::size_t c = 0; c < kColumns.size(); ++c) {
      const auto value = finite_number(fields[(*column_of)[c]]);
      if (!value) {
        throw fail(number, std::string("column '") + std::string(kColumns[c]) + "': '" +
                               std::string(fields[(*column_of)[c]]) + "' is not a number");
      }
      values[c] = *value;
    }
    TimedPose pose{values[0], {values[1], values[2], values[3]}};
    if (has_spread) {
      std::array<double, 4> spread{};
      for (std::size_t c = 0; c < kSpreadColumns.size(); ++c) {
        if (!spread_column_of[c]) continue;
        const auto value = finite_number(fields[*spread_column_of[c]]);
        if (!value) {
          throw fail(number, std::string("column '") + std::string(kSpreadColumns[c]) + "': '" +
                                 std::string(fields[*spread_column_of[c]]) + "' is not a number");
        }
        spread[c] = *value;
      }
      pose.spread = PoseSpread{spread[0] * spread[0], spread[1] * spread[1], spread[3], spread[2] * spread[2]};
    }
    trajectory.push_back(pose);
  }
  if (!column_of) throw std::runtime_error(std::string(name) + ": no header line (time,x,y,yaw)");
  return trajectory;
}

Trajectory read_trajectory_csv(const std::filesystem::path& path) {
  // Plain or gzip, as every file the tools write may be (`localize -o est.csv.gz`).
  auto in = log::open_log_input(path);
  auto trajectory = read_trajectory_csv(*in, path.string());
  if (const auto error = in->error()) throw std::runtime_error(path.string() + ": " + *error);
  return trajectory;
}

void write_trajectory_csv(std::ostream& out, const Trajectory& trajectory) {
  out << "time,x,y,yaw\n";
  char row[160];
  for (const auto& entry : trajectory) {
    std::snprintf(row, sizeof row, "%.9f,%.9f,%.9f,%.9f\n", entry.time, entry.pose.x, entry.pose.y, entry.pose.yaw);
    out << row;
  }
}

Trajectory truth_from_log(const std::filesystem::path& log, LoggedScanReaderOptions options) {
  Trajectory samples;
  options.on_truth = [&samples](double time, const geometry::Pose2& pose) { samples.push_back({time, pose}); };
  LoggedScanReader reader(log, options);
  Trajectory by_scan;
  while (auto scan = reader.next()) {
    if (scan->truth) by_scan.push_back({scan->time, *scan->truth});
  }
  if (reader.format() != log::LogFormat::kPlayer || reader.clock().synthetic() || samples.empty()) return by_scan;
  std::stable_sort(samples.begin(), samples.end(),
                   [](const TimedPose& a, const TimedPose& b) { return a.time < b.time; });
  return samples;
}

}  // namespace playerkit::localization
