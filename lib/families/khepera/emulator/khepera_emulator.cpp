#include "families/khepera/emulator/khepera_emulator.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <utility>

namespace playerkit::emulators {

namespace hw = hardware::khepera;
using namespace std::chrono_literals;

namespace {

constexpr Duration kTick = 10ms;  // the BIOS's speed period
constexpr double kTickSeconds = hw::kSpeedPeriodSeconds;
constexpr double kMillimetresPerMetre = 1000.0;

// khepera.md §3.4, mm, mm, degrees.
std::vector<geometry::Pose2> sheet_ir_poses() {
  constexpr double kDegree = std::numbers::pi / 180.0;
  const double poses[8][3] = {{10, 24, 90},   {19, 17, 45},    {25, 6, 0},      {25, -6, 0},
                              {19, -17, -45}, {10, -24, -90}, {-24, -10, 180}, {-24, 10, 180}};
  std::vector<geometry::Pose2> ring;
  for (const auto& pose : poses) {
    ring.push_back({pose[0] / kMillimetresPerMetre, pose[1] / kMillimetresPerMetre, pose[2] * kDegree});
  }
  return ring;
}

mobile_base::DriveGeometry drive_geometry(const KheperaEmulatorOptions& options) {
  const double fastest = hw::wheel_metres_per_second(hw::kFastestWheel, options.wheels);
  const double wheelbase = options.wheels.wheelbase_mm / kMillimetresPerMetre;
  return {.wheelbase = wheelbase,
          .footprint_radius = options.footprint_radius,
          .max_speed = fastest,
          .max_turn_rate = 2.0 * fastest / wheelbase};
}

// The 32-bit counter as the BIOS prints it.
std::int64_t as_counter(std::int64_t value) { return static_cast<std::int32_t>(static_cast<std::uint32_t>(value)); }

}  // namespace

KheperaEmulator::KheperaEmulator(KheperaEmulatorOptions options)
    : options_(std::move(options)),
      drive_(drive_geometry(options_), options_.odometry_error, options_.map, options_.initial_pose),
      ring_(options_.ir_poses.empty() ? sheet_ir_poses() : options_.ir_poses) {}

std::int64_t KheperaEmulator::left_counter() const { return as_counter(left_origin_ + std::llround(left_pulses_)); }
std::int64_t KheperaEmulator::right_counter() const {
  return as_counter(right_origin_ + std::llround(right_pulses_));
}

std::vector<std::int64_t> KheperaEmulator::proximity() const {
  // Nothing within the calibration's reach reads 1, its farthest.
  const double reach = options_.ir_calibration.a / kMillimetresPerMetre;
  std::vector<std::int64_t> readings;
  for (int i = 0; i < ring_.size(); ++i) {
    const double range = ring_.range(i, options_.map, drive_.true_pose(), reach);
    readings.push_back(range >= reach ? 1 : hw::ir_reading(range * kMillimetresPerMetre, options_.ir_calibration));
  }
  return readings;
}

void KheperaEmulator::receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) {
  advance(now);
  if (options_.model_baud != 0 && host_baud != 0 && host_baud != options_.model_baud) {
    typed_.clear();  // noise at another speed: whatever was being typed is lost
    return;
  }
  for (const std::uint8_t byte : bytes) {
    if (byte == '\n' || byte == '\r') {
      if (!typed_.empty()) execute(typed_);
      typed_.clear();
    } else if (typed_.size() < hw::kLongestLine) {
      typed_.push_back(static_cast<char>(byte));
    }
  }
}

void KheperaEmulator::execute(std::string_view line) {
  const auto command = hw::parse_line(line);
  if (!command) return;
  ++commands_;
  const auto values = answer(*command);
  if (!values) return;
  const auto bytes = hw::encode_reply({command->letter, *values});
  output_.push_back({bytes, /*has_checksum=*/false});
}

std::optional<std::vector<std::int64_t>> KheperaEmulator::answer(const hw::Message& command) {
  const auto& values = command.values;
  switch (command.letter) {
    case hw::letter::set_speed: {
      if (values.size() != 2) return std::nullopt;
      const auto limit = [](std::int64_t speed) {
        return std::clamp<std::int64_t>(speed, -hw::kFastestWheel, hw::kFastestWheel);
      };
      speeds_ = {limit(values[0]), limit(values[1])};
      ++set_speed_commands_;
      drive_.command_wheels({hw::wheel_metres_per_second(static_cast<double>(speeds_.left), options_.wheels),
                             hw::wheel_metres_per_second(static_cast<double>(speeds_.right), options_.wheels)});
      return std::vector<std::int64_t>{};
    }
    case hw::letter::read_speed: return std::vector<std::int64_t>{speeds_.left, speeds_.right};
    case hw::letter::set_position:
      if (values.size() != 2) return std::nullopt;
      left_origin_ = values[0];
      right_origin_ = values[1];
      left_pulses_ = right_pulses_ = 0.0;
      return std::vector<std::int64_t>{};
    case hw::letter::read_position: return std::vector<std::int64_t>{left_counter(), right_counter()};
    case hw::letter::read_proximity: return proximity();
    default: return std::nullopt;
  }
}

void KheperaEmulator::advance(Duration now) {
  if (!drive_.commanded_to_move()) {
    // Idle wheels turn nothing: the ticks only need to keep their phase.
    if (now >= next_tick_) next_tick_ = now - (now - next_tick_) % kTick + kTick;
    return;
  }
  while (next_tick_ <= now) {
    tick();
    next_tick_ += kTick;
  }
}

void KheperaEmulator::tick() {
  const geometry::Pose2 before = drive_.odometry();
  drive_.run(kTickSeconds, kTickSeconds);
  const geometry::Pose2 after = drive_.odometry();
  // The step in the odometry as the wheels turned it: the arc's length from
  // its chord and its turn.
  const geometry::Pose2 step = before.inverse().compose(after);
  const double turn = geometry::normalize_angle(after.yaw - before.yaw);
  const double chord = std::copysign(std::hypot(step.x, step.y), step.x);
  const double arc = std::abs(turn) > 1e-12 ? chord * (turn / 2.0) / std::sin(turn / 2.0) : chord;
  const double half_track = options_.wheels.wheelbase_mm / kMillimetresPerMetre / 2.0;
  const double metres_per_pulse = options_.wheels.millimetres_per_pulse / kMillimetresPerMetre;
  left_pulses_ += (arc - turn * half_track) / metres_per_pulse;
  right_pulses_ += (arc + turn * half_track) / metres_per_pulse;
}

Duration KheperaEmulator::next_deadline() const {
  return drive_.commanded_to_move() ? next_tick_ : Duration::max();
}

std::vector<Telegram> KheperaEmulator::take_output() { return std::exchange(output_, {}); }

std::string KheperaEmulator::describe() const {
  std::ostringstream text;
  const geometry::Pose2& pose = drive_.true_pose();
  text << "Khepera, wheels " << speeds_.left << "," << speeds_.right << " pulses/10 ms, counters " << left_counter()
       << "," << right_counter() << ", at (" << pose.x << ", " << pose.y << ") m, "
       << pose.yaw * 180.0 / std::numbers::pi << " deg";
  return text.str();
}

}  // namespace playerkit::emulators
