#include "families/cmucam2/emulator/cmucam2_emulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

namespace playerkit::emulators {

namespace cam = hardware::cmucam2;

namespace {

constexpr std::size_t kLongestCommand = 80;  // a runaway line is cut, as the camera's buffer is

}  // namespace

Cmucam2Emulator::Cmucam2Emulator(cmucam2::Scene scene, Cmucam2EmulatorOptions options)
    : scene_(std::move(scene)), options_(options) {}

cmucam2::Scene Cmucam2Emulator::default_scene() {
  return cmucam2::Scene({{.pan = 10, .tilt = 0, .radius = 6, .color = {220, 30, 30}},
                         {.pan = -15, .tilt = 5, .radius = 4, .color = {30, 200, 40}}},
                        {25, 25, 25});
}

void Cmucam2Emulator::receive(std::span<const std::uint8_t> bytes, Duration now, int /*host_baud*/) {
  advance(now);
  for (const std::uint8_t byte : bytes) {
    if (byte != '\r') {
      if (typed_.size() < kLongestCommand) typed_.push_back(static_cast<char>(byte));
      continue;
    }
    execute(std::exchange(typed_, {}));
  }
}

void Cmucam2Emulator::say(const std::string& text) {
  output_.push_back({std::vector<std::uint8_t>(text.begin(), text.end()), false});
}

void Cmucam2Emulator::execute(const std::string& line) {
  // Any command ends a stream (and a packet not yet sent).
  next_packet_.reset();
  const std::string idle(1, static_cast<char>(cam::kPrompt));
  const auto ack = [&](const std::string& extra = "") { say("ACK\r" + extra + idle); };
  const auto nck = [&] {
    ++refused_;
    say("NCK\r" + idle);
  };
  if (line.find_first_not_of(' ') == std::string::npos) return ack();
  const auto command = cam::parse_command(line);
  if (!command) return nck();
  const std::vector<int>& args = command->arguments;
  const std::string& name = command->name;
  if (name == "PM" && args.size() == 1 && (args[0] == 0 || args[0] == 1)) {
    poll_mode_ = args[0] == 1;
    return ack();
  }
  if (name == "TC" && (args.size() == 6 || (args.empty() && tracked_))) {
    if (args.size() == 6) {
      // Never NCK a TC (cmucam2.md §6.4: the 1.5 driver would hang): bounds
      // beyond a byte are taken at the byte's end; crossed ones match nothing.
      const auto byte = [](int value) { return std::clamp(value, 0, 255); };
      tracked_ = cam::ColorBounds{byte(args[0]), byte(args[1]), byte(args[2]),
                                  byte(args[3]), byte(args[4]), byte(args[5])};
    }
    say("ACK\r");
    next_packet_ = now_ + options_.frame_period;
    return;
  }
  if (name == "SV" && args.size() == 2 && args[0] >= 0 && args[0] < kServos && args[1] >= 0 && args[1] <= 255) {
    servos_[static_cast<std::size_t>(args[0])].target = args[1];
    return ack();
  }
  if (name == "GS" && args.size() == 1 && args[0] >= 0 && args[0] < kServos) {
    return ack(std::to_string(servos_[static_cast<std::size_t>(args[0])].target) + "\r");
  }
  if (name == "GV" && args.empty()) return ack(std::string(kVersion) + "\r");
  if (name == "RS" && args.empty()) {
    poll_mode_ = false;
    tracked_.reset();
    for (Servo& servo : servos_) servo.target = kServoCentre;
    return ack(std::string(kVersion) + "\r");
  }
  // Servo mask (CMUcam2 manual: bits 0/1 pan/tilt auto-servo, 2/3 pan/tilt report, 0..15): Player 2.x's cmucam2
  // sends `SM 0` at start-up and `SM 15` to auto-servo. Accepted as the camera does; auto-servoing (the camera
  // turning toward the tracked blob) is not emulated, the servos stay where SV puts them.
  if (name == "SM" && args.size() == 1 && args[0] >= 0 && args[0] <= 15) return ack();
  // Power and camera registers: accepted, nothing to emulate (1.5's camera.c has them).
  if ((name == "CP" && args.size() == 1) || (name == "CR" && !args.empty() && args.size() % 2 == 0)) return ack();
  nck();
}

void Cmucam2Emulator::send_packet() {
  ++packets_;
  const cam::TPacket packet = cmucam2::track(scene_, *tracked_, pan_degrees(), tilt_degrees());
  std::string text = cam::t_packet_line(packet) + "\r";
  if (poll_mode_) {
    if (options_.prompt_after_packet) text += static_cast<char>(cam::kPrompt);
    next_packet_.reset();
  } else {
    *next_packet_ += options_.frame_period;
  }
  say(text);
}

void Cmucam2Emulator::move_servos(Duration until) {
  if (until <= now_) return;
  const double step = options_.servo_speed * std::chrono::duration<double>(until - now_).count();
  for (Servo& servo : servos_) {
    const double to_go = servo.target - servo.position;
    servo.position = std::fabs(to_go) <= step ? servo.target : servo.position + std::copysign(step, to_go);
  }
  now_ = until;
}

void Cmucam2Emulator::advance(Duration now) {
  // Each frame sees the servos where they were when it was taken.
  while (next_packet_ && *next_packet_ <= now) {
    move_servos(*next_packet_);
    send_packet();
  }
  move_servos(now);
}

double Cmucam2Emulator::pan_degrees() const {
  return (servos_[0].position - kServoCentre) * options_.degrees_per_position;
}

double Cmucam2Emulator::tilt_degrees() const {
  return (servos_[1].position - kServoCentre) * options_.degrees_per_position;
}

Duration Cmucam2Emulator::next_deadline() const { return next_packet_.value_or(Duration::max()); }

std::vector<Telegram> Cmucam2Emulator::take_output() { return std::exchange(output_, {}); }

std::string Cmucam2Emulator::describe() const {
  char text[200];
  std::snprintf(text, sizeof text, "CMUcam2 seeing %s, pan %.1f tilt %.1f deg, %s%s, %llu packets",
                scene_.describe().c_str(), pan_degrees(), tilt_degrees(), poll_mode_ ? "poll mode" : "streaming mode",
                next_packet_ ? ", tracking" : "", static_cast<unsigned long long>(packets_));
  return text;
}

}  // namespace playerkit::emulators
