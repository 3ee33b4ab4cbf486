#include "families/sonyevid30/emulator/evid30_emulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <stdexcept>
#include <utility>

#include "families/sonyevid30/protocol/evid30_units.hpp"

namespace playerkit::emulators {

namespace visca = hardware::sonyevid30;
using visca::HostMessage;
using namespace std::chrono_literals;

namespace {

// How often motion is worked out while something moves.
constexpr Duration kMotionStep = 10ms;
// Zoom drive speeds run 1..8 (p + 1 of `2p`/`3p`).
constexpr double kZoomDriveSteps = 8;

// Inquiries the camera answers beyond pan/tilt and zoom. Player 2.x and 3.x's sonyevid30 asks for these two at
// start-up (the sheet's 1.5 driver never does): CAM_PowerInq `8x 09 04 00 FF` -> `y0 50 02 FF` (on; 03 is
// standby), and the device-type inquiry `8x 09 00 02 FF` -> `y0 50 00 20 04 02 rr rr 02 FF` (vendor 0020 Sony,
// model 0402 the EVI-D30/D31, a ROM version, 2 sockets). Any other inquiry is not modelled but still answered
// (`90 50 00 FF`): a host waiting for an answer must get one (sheet §6.6).
visca::Bytes other_inquiry_reply(std::span<const std::uint8_t> packet) {
  const auto is = [&](std::initializer_list<std::uint8_t> body) {
    return packet.size() == body.size() + 2 && std::equal(body.begin(), body.end(), packet.begin() + 1);
  };
  if (is({0x09, 0x04, 0x00})) return visca::answer_reply(std::array<std::uint8_t, 1>{0x02});
  if (is({0x09, 0x00, 0x02})) {
    return visca::answer_reply(std::array<std::uint8_t, 7>{0x00, 0x20, 0x04, 0x02, 0x01, 0x18, 0x02});
  }
  return visca::answer_reply(std::array<std::uint8_t, 1>{0x00});
}

}  // namespace

Evid30Emulator::Evid30Emulator(Evid30EmulatorOptions options) : options_(options) {
  if (!(options_.pan_top_speed > 0) || !(options_.tilt_top_speed > 0) || !(options_.zoom_travel_seconds > 0)) {
    throw std::invalid_argument("sonyevid30 emulator: the top speeds and the zoom travel time must be above 0");
  }
  axes_[kPan] = {.min = visca::kPanMinUnits, .max = visca::kPanMaxUnits};
  axes_[kTilt] = {.min = visca::kTiltMinUnits, .max = visca::kTiltMaxUnits};
  axes_[kZoom] = {.min = 0, .max = visca::kZoomMaxUnits};
}

void Evid30Emulator::receive(std::span<const std::uint8_t> bytes, Duration now, int /*host_baud*/) {
  advance(now);  // inquiries report where the camera is now
  for (const std::uint8_t byte : bytes) {
    // A header starts a packet wherever it comes: what came before it had lost its terminator.
    if ((byte & 0xF0) == 0x80 && byte != visca::kTerminator) received_.clear();
    if (received_.empty() && (byte & 0xF0) != 0x80) continue;  // noise between packets
    received_.push_back(byte);
    if (byte == visca::kTerminator) {
      execute(received_);
      received_.clear();
    } else if (received_.size() > visca::kLongestMessage + 1) {
      ++syntax_errors_;
      send(visca::error_reply(0, visca::kSyntaxError));
      received_.clear();
    }
  }
}

void Evid30Emulator::execute(std::span<const std::uint8_t> packet) {
  const HostMessage message = visca::parse_host_message(packet);
  switch (message.kind) {
    case HostMessage::Kind::pan_tilt_inquiry:
      send(visca::pan_tilt_reply({.pan = static_cast<int>(std::lround(axes_[kPan].position)),
                                  .tilt = static_cast<int>(std::lround(axes_[kTilt].position))}));
      return;
    case HostMessage::Kind::zoom_inquiry:
      send(visca::zoom_reply(static_cast<int>(std::lround(axes_[kZoom].position))));
      return;
    case HostMessage::Kind::other_inquiry:
      send(other_inquiry_reply(packet));
      return;
    case HostMessage::Kind::address_set:
      send({visca::kBroadcast, 0x30, 0x02, visca::kTerminator});  // the next camera would be 2
      return;
    case HostMessage::Kind::if_clear:
      send({visca::kBroadcast, 0x01, 0x00, 0x01, visca::kTerminator});
      return;
    case HostMessage::Kind::cancel: {
      ++cancels_;
      auto& held = sockets_[message.socket - 1];
      if (!held) {
        send(visca::error_reply(message.socket, visca::kNoSocket));
        return;
      }
      hold(*held);
      held.reset();
      send(visca::error_reply(message.socket, visca::kCancelled));
      return;
    }
    case HostMessage::Kind::malformed:
      ++syntax_errors_;
      send(visca::error_reply(0, visca::kSyntaxError));
      return;
    default:
      ++commands_;
      command(message);
      return;
  }
}

void Evid30Emulator::command(const HostMessage& message) {
  std::optional<Function> function;
  if (message.kind == HostMessage::Kind::absolute_pan_tilt || message.kind == HostMessage::Kind::drive_pan_tilt) {
    function = kPanTilt;
  } else if (message.kind == HostMessage::Kind::zoom_direct || message.kind == HostMessage::Kind::zoom_drive) {
    function = kZoomFunction;
  }
  // A command of a kind still running ends that one: it completes where the new one takes over.
  for (std::size_t i = 0; i < sockets_.size(); ++i) {
    if (function && sockets_[i] == function) {
      sockets_[i].reset();
      send(visca::completion(static_cast<int>(i + 1)));
    }
  }
  const auto free = std::find(sockets_.begin(), sockets_.end(), std::nullopt);
  if (free == sockets_.end()) {
    send(visca::error_reply(0, visca::kBufferFull));
    return;
  }
  const int socket = static_cast<int>(free - sockets_.begin()) + 1;
  send(visca::ack(socket));
  start(message);
  if (function && in_motion(*function) && message.kind != HostMessage::Kind::drive_pan_tilt &&
      message.kind != HostMessage::Kind::zoom_drive) {
    *free = function;  // completes when the target is reached (advance)
  } else {
    send(visca::completion(socket));
  }
}

void Evid30Emulator::start(const HostMessage& message) {
  const double pan_speed = message.pan_speed / double(visca::kPanSpeedMax) * options_.pan_top_speed *
                           visca::kPanUnitsPerDegree;
  const double tilt_speed = message.tilt_speed / double(visca::kTiltSpeedMax) * options_.tilt_top_speed *
                            visca::kTiltUnitsPerDegree;
  const double zoom_top_speed = visca::kZoomMaxUnits / options_.zoom_travel_seconds;
  auto aim = [](AxisState& axis, double target, double speed) {
    axis = {.position = axis.position, .target = std::clamp(target, axis.min, axis.max), .speed = speed,
            .driving = false, .min = axis.min, .max = axis.max};
  };
  auto drive = [](AxisState& axis, double signed_speed) {
    axis.driving = signed_speed != 0;
    axis.speed = signed_speed;
    axis.target = axis.position;
  };
  switch (message.kind) {
    case HostMessage::Kind::absolute_pan_tilt:
      aim(axes_[kPan], message.pan, pan_speed);
      aim(axes_[kTilt], message.tilt, tilt_speed);
      break;
    case HostMessage::Kind::drive_pan_tilt: {
      // Pan: 01 left (camera units falling), 02 right; tilt: 01 up, 02 down.
      auto signed_speed = [](visca::Drive how, double speed, double rising) {
        return how == visca::Drive::stop ? 0.0 : how == visca::Drive::forward ? -rising * speed : rising * speed;
      };
      drive(axes_[kPan], signed_speed(message.drive_pan, pan_speed, 1));
      drive(axes_[kTilt], signed_speed(message.drive_tilt, tilt_speed, -1));
      break;
    }
    case HostMessage::Kind::zoom_direct:
      aim(axes_[kZoom], message.zoom, zoom_top_speed);
      break;
    case HostMessage::Kind::zoom_drive:
      drive(axes_[kZoom], message.zoom_speed / kZoomDriveSteps * zoom_top_speed);
      break;
    default:
      break;
  }
}

void Evid30Emulator::hold(Function function) {
  auto stop = [](AxisState& axis) {
    axis.target = axis.position;
    axis.driving = false;
  };
  if (function == kPanTilt) {
    stop(axes_[kPan]);
    stop(axes_[kTilt]);
  } else {
    stop(axes_[kZoom]);
  }
}

bool Evid30Emulator::moving(const AxisState& axis) const {
  if (axis.driving) return (axis.speed > 0 && axis.position < axis.max) || (axis.speed < 0 && axis.position > axis.min);
  return axis.position != axis.target;
}

bool Evid30Emulator::in_motion(Function function) const {
  return function == kPanTilt ? moving(axes_[kPan]) || moving(axes_[kTilt]) : moving(axes_[kZoom]);
}

void Evid30Emulator::advance(Duration now) {
  if (now <= now_) return;
  const double seconds = std::chrono::duration<double>(now - now_).count();
  now_ = now;
  for (AxisState& axis : axes_) {
    if (axis.driving) {
      axis.position = std::clamp(axis.position + axis.speed * seconds, axis.min, axis.max);
      continue;
    }
    const double to_go = axis.target - axis.position;
    const double step = axis.speed * seconds;
    axis.position = std::fabs(to_go) <= step ? axis.target : axis.position + std::copysign(step, to_go);
  }
  for (std::size_t i = 0; i < sockets_.size(); ++i) {
    if (sockets_[i] && !in_motion(*sockets_[i])) {
      sockets_[i].reset();
      send(visca::completion(static_cast<int>(i + 1)));
    }
  }
}

Duration Evid30Emulator::next_deadline() const {
  const bool anything_moves = std::any_of(axes_.begin(), axes_.end(), [this](const AxisState& a) { return moving(a); });
  return anything_moves ? now_ + kMotionStep : Duration::max();
}

int Evid30Emulator::busy_sockets() const {
  return static_cast<int>(std::count_if(sockets_.begin(), sockets_.end(), [](const auto& s) { return s.has_value(); }));
}

void Evid30Emulator::send(visca::Bytes bytes) {
  // No checksum, but a "bad checksum" fault spoils the last byte: a lost terminator is VISCA's damaged packet.
  output_.push_back({std::move(bytes), true});
}

std::vector<Telegram> Evid30Emulator::take_output() { return std::exchange(output_, {}); }

std::string Evid30Emulator::describe() const {
  char text[160];
  std::snprintf(text, sizeof text, "Sony EVI-D30, pan %.1f tilt %.1f degrees, zoom %ld, %d socket(s) busy",
                visca::pan_degrees(static_cast<int>(std::lround(pan_units()))),
                visca::tilt_degrees(static_cast<int>(std::lround(tilt_units()))), std::lround(zoom_units()),
                busy_sockets());
  return text;
}

}  // namespace playerkit::emulators
