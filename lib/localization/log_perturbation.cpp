// perturb_log (odometry_perturbation.hpp): the line-level rewriting of Player
// and CARMEN logs around an OdometryPerturber.

#include <cmath>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "log/text_log_tokens.hpp"
#include "localization/odometry_perturbation.hpp"
#include "log/carmen_log_parser.hpp"
#include "log/carmen_log_reader.hpp"
#include "log/log_input.hpp"
#include "log/log_parse_error.hpp"
#include "log/text_log_reader.hpp"
#include "protocol/interfaces.hpp"
#include "text/line_reader.hpp"

namespace playerkit::localization {
namespace {

using log::format_text;
using log::LineToken;
using log::replace_tokens;
using log::split_line_tokens;

double path_step(const std::optional<geometry::Pose2>& from, const geometry::Pose2& to) {
  return from ? std::hypot(to.x - from->x, to.y - from->y) : 0.0;
}

// Lines with their own end: a last line without '\n' stays without one.
class LineCopier {
 public:
  explicit LineCopier(const std::filesystem::path& path) : in_(log::open_log_input(path)), name_(path.string()) {}

  bool next(std::string& line) {
    if (!text::read_line(*in_, line, name_, number_ + 1)) {
      if (const auto error = in_->error()) throw std::runtime_error(name_ + ": " + *error);
      return false;
    }
    ++number_;
    ended_by_newline_ = !in_->eof();
    return true;
  }
  const char* end() const { return ended_by_newline_ ? "\n" : ""; }
  int number() const { return number_; }
  const std::string& name() const { return name_; }

 private:
  std::unique_ptr<log::LogInput> in_;
  std::string name_;
  int number_ = 0;
  bool ended_by_newline_ = true;
};

void finish_summary(PerturbationSummary& summary, const OdometryPerturber* stream) {
  if (!stream || !stream->last_true_pose()) return;
  const geometry::Pose2 truth = *stream->last_true_pose();
  const geometry::Pose2 odometry = *stream->last_odometry_pose();
  summary.odometry_input_path_m = stream->true_path_length_m();
  summary.final_position_drift_m = std::hypot(odometry.x - truth.x, odometry.y - truth.y);
  summary.final_heading_drift_rad = geometry::angle_difference(odometry.yaw, truth.yaw);
}

// ---- CARMEN ----

std::string carmen_number(double value) { return format_text("%f", value); }

// The token where a laser record's odometry pose starts (see carmen_log.hpp
// for the layouts), or nullopt when the record has none.
std::optional<std::size_t> carmen_odometry_token(const log::CarmenLaser& laser) {
  if (!laser.robot_pose) return std::nullopt;
  using K = log::CarmenLaserKind;
  const std::size_t beams = laser.ranges.size();
  if (laser.kind == K::kFlaser || laser.kind == K::kRlaser) return 1 + 1 + beams + 3;
  if (laser.kind == K::kRobotLaser1 || laser.kind == K::kRobotLaser2) {
    return 1 + 7 + 1 + beams + 1 + laser.remissions.size() + 3;
  }
  return std::nullopt;
}

bool carmen_lasers_carry_odometry(const std::filesystem::path& path) {
  auto in = log::open_log_input(path);
  log::CarmenLogReader reader(*in, path.string());
  while (auto record = reader.next()) {
    const auto* laser = std::get_if<log::CarmenLaser>(&*record);
    if (laser && carmen_odometry_token(*laser)) return true;
  }
  return false;
}

// The odometry pose of a CARMEN line and where it is, if it has one.
struct CarmenOdometryField {
  std::size_t first_token = 0;
  geometry::Pose2 pose;
  bool from_laser = false;
};

// The yaw as written (not wrapped), so that an unperturbed field prints back unchanged.
geometry::Pose2 pose_as_logged(const log::CarmenPose& pose) { return {pose.x, pose.y, pose.theta}; }

PerturbationSummary perturb_carmen(const std::filesystem::path& path, std::ostream& out,
                                   const OdometryErrorModel& model, std::uint64_t seed) {
  PerturbationSummary summary;
  summary.format = log::LogFormat::kCarmen;
  // When laser records carry odometry, their poses alone drive the model and
  // ODOM lines keep their offset from the latest one (see README.md).
  const bool laser_driven = carmen_lasers_carry_odometry(path);
  OdometryPerturber stream(model, seed);
  std::optional<geometry::Pose2> anchor_in, anchor_out;
  std::optional<geometry::Pose2> last_truth;
  LineCopier lines(path);
  std::string line;
  while (lines.next(line)) {
    std::optional<CarmenOdometryField> field;
    try {
      const auto parsed = log::parse_carmen_line(line, lines.name(), lines.number());
      if (const auto* record = std::get_if<log::CarmenRecord>(&parsed)) {
        if (const auto* odom = std::get_if<log::CarmenOdometry>(record)) {
          field = CarmenOdometryField{1, pose_as_logged(odom->pose), false};
        } else if (const auto* truepos = std::get_if<log::CarmenTruePos>(record)) {
          field = CarmenOdometryField{4, pose_as_logged(truepos->odometry_pose), false};
        } else if (const auto* laser = std::get_if<log::CarmenLaser>(record)) {
          if (const auto first = carmen_odometry_token(*laser)) {
            field = CarmenOdometryField{*first, pose_as_logged(*laser->robot_pose), true};
          }
          const bool front = laser->kind == log::CarmenLaserKind::kFlaser ||
                             laser->kind == log::CarmenLaserKind::kRobotLaser1;
          if (front && laser->laser_pose) {
            const geometry::Pose2 truth = pose_as_logged(*laser->laser_pose);
            summary.truth_path_m += path_step(last_truth, truth);
            last_truth = truth;
          }
        }
      }
    } catch (const log::LogParseError&) {
      ++summary.malformed_lines;
    }
    std::optional<geometry::Pose2> degraded;
    if (field && (field->from_laser || !laser_driven)) {
      degraded = stream.next(field->pose);
      anchor_in = field->pose;
      anchor_out = degraded;
    } else if (field && anchor_in) {
      degraded = anchor_out->compose(anchor_in->between(field->pose));
    }
    if (!degraded) {  // not odometry, or odometry before the model's first pose: no error yet
      out << line << lines.end();
      continue;
    }
    const auto tokens = split_line_tokens(line);
    out << replace_tokens(line, tokens, field->first_token,
                          {carmen_number(degraded->x), carmen_number(degraded->y), carmen_number(degraded->yaw)})
        << lines.end();
    ++summary.odometry_poses_changed;
  }
  finish_summary(summary, &stream);
  return summary;
}

// ---- Player ----

std::string player_length(double metres) { return format_text("%+07.3f", metres); }
std::string player_angle(double radians) { return format_text("%+04.3f", radians); }

bool player_log_has_truth(const std::filesystem::path& path) {
  LineCopier lines(path);
  std::string line;
  while (lines.next(line)) {
    const auto tokens = split_line_tokens(line);
    if (tokens.size() > log::kInterfaceColumn && tokens[log::kInterfaceColumn].text == "truth") return true;
  }
  return false;
}

std::string player_truth_line(const std::vector<LineToken>& position_tokens, const geometry::Pose2& pose,
                              log::LogFormatVersion version, const char* end) {
  std::string line;
  for (std::size_t i = 0; i < log::kInterfaceColumn; ++i) line.append(position_tokens[i].text).append(" ");
  line.append("truth ")
      .append(position_tokens[log::kIndexColumn].text)
      .append(" ")
      .append(position_tokens[log::kDataTimeColumn].text)
      .append(" ");
  line += player_length(pose.x) + " " + player_length(pose.y) + " ";
  if (version == log::LogFormatVersion::k0_2_0) {
    // 1.6.5's truth is 3-D: z, roll and pitch are written 0, as the writer does.
    line += player_length(0) + " " + player_angle(0) + " " + player_angle(0) + " ";
  }
  line += player_angle(pose.yaw);
  return line + end;
}

PerturbationSummary perturb_player(const std::filesystem::path& path, std::ostream& out,
                                   const OdometryErrorModel& model, std::uint64_t seed) {
  PerturbationSummary summary;
  summary.format = log::LogFormat::kPlayer;
  const bool add_truth = !player_log_has_truth(path);
  std::map<std::uint16_t, OdometryPerturber> streams;
  std::optional<geometry::Pose2> last_truth;
  auto version = log::LogFormatVersion::k0_0_0;
  LineCopier lines(path);
  std::string line;
  while (lines.next(line)) {
    std::optional<std::uint16_t> position_index;
    try {
      const auto parsed = log::parse_log_line(line, lines.name(), lines.number(), version);
      if (const auto* header = std::get_if<log::HeaderLine>(&parsed)) {
        if (header->name == "File version") {
          if (const auto known = log::parse_format_version(header->value)) version = *known;
        }
      } else if (const auto* data = std::get_if<log::DataLine>(&parsed)) {
        if (data->device && !data->message.payload.empty()) {
          if (data->device->interface == protocol::kPositionCode) position_index = data->device->index;
          if (data->device->interface == protocol::kTruthCode && data->device->index == 0) {
            const auto pose = log::read_text_pose(log::split_line_tokens(line),
                                                  version == log::LogFormatVersion::k0_2_0);
            const geometry::Pose2 truth{pose.x, pose.y, pose.yaw};
            summary.truth_path_m += path_step(last_truth, truth);
            last_truth = truth;
          }
        }
      }
    } catch (const log::LogParseError&) {
      ++summary.malformed_lines;
    }
    if (!position_index) {
      out << line << lines.end();
      continue;
    }
    const auto tokens = log::split_line_tokens(line);
    const auto pose = log::read_text_pose(tokens, false);
    const geometry::Pose2 original{pose.x, pose.y, geometry::normalize_angle(pose.yaw)};
    auto stream = streams.find(*position_index);
    if (stream == streams.end()) {
      // Each index its own stream; seed_seq keeps the streams of one seed apart.
      std::seed_seq seeds{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                          static_cast<std::uint32_t>(*position_index)};
      std::vector<std::uint32_t> words(2);
      seeds.generate(words.begin(), words.end());
      const std::uint64_t stream_seed = (static_cast<std::uint64_t>(words[0]) << 32) | words[1];
      stream = streams.emplace(*position_index, OdometryPerturber(model, stream_seed)).first;
    }
    const auto degraded = stream->second.next(original);
    const bool truth_follows = add_truth && *position_index == 0;
    out << replace_tokens(line, tokens, log::kFirstFieldColumn,
                          {player_length(degraded.x), player_length(degraded.y), player_angle(degraded.yaw)})
        << (truth_follows ? "\n" : lines.end());
    ++summary.odometry_poses_changed;
    if (truth_follows) {
      out << player_truth_line(tokens, original, version, lines.end());
      ++summary.truth_lines_added;
      summary.truth_path_m += path_step(last_truth, original);
      last_truth = original;
    }
  }
  const auto main_stream = streams.find(0);
  finish_summary(summary, main_stream != streams.end() ? &main_stream->second
                          : streams.empty()           ? nullptr
                                                      : &streams.begin()->second);
  return summary;
}

}  // namespace

PerturbationSummary perturb_log(const std::filesystem::path& in, std::ostream& out,
                                const OdometryErrorModel& model, std::uint64_t seed) {
  return log::detect_log_format(in) == log::LogFormat::kCarmen ? perturb_carmen(in, out, model, seed)
                                                               : perturb_player(in, out, model, seed);
}

}  // namespace playerkit::localization
