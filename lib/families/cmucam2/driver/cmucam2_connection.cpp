#include "families/cmucam2/driver/cmucam2_connection.hpp"

#include <algorithm>
#include <cmath>

#include "core/driver.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/blobfinder.hpp"
#include "protocol/messages/ptz.hpp"

namespace playerkit::drivers::cmucam2 {

namespace {

using namespace std::chrono_literals;

// Without a blobfinder the camera paces nothing: the servos are read at
// the rate 1.5's ptz drivers published.
constexpr auto kServoPeriod = 100ms;
// While a servo steps toward its target at a speed, how often it steps.
constexpr auto kStepPeriod = 20ms;
// How long a camera may stay silent at the first subscription.
constexpr auto kBootTime = 2500ms;
// The frame the T packets count in: the CMUcam2's low-resolution window (1.5 said 83 x 143).
constexpr std::uint16_t kFrameWidth = 88;
constexpr std::uint16_t kFrameHeight = 143;

std::int16_t wire_degrees(double degrees) { return static_cast<std::int16_t>(std::lround(degrees)); }

}  // namespace

std::string connection_key(const Cmucam2Settings& settings) { return "cmucam2 " + settings.port; }

Cmucam2Connection::Cmucam2Connection(Cmucam2Settings settings, core::Logger& logger)
    : RobotConnection(settings.port, {.baud = 115200}, logger, "cmucam2 " + settings.port),
      settings_(std::move(settings)),
      colors_(settings_.colors) {}

Cmucam2Connection::~Cmucam2Connection() { stop_io_thread(); }

void Cmucam2Connection::add_device(Cmucam2Role role, core::Device& device) {
  serve_device(device);  // throws while the camera is away
  std::lock_guard lock(views_mutex_);
  views_.push_back({role, &device});
}

void Cmucam2Connection::remove_device(core::Device& device) {
  {
    std::lock_guard lock(views_mutex_);
    std::erase_if(views_, [&](const View& view) { return view.device == &device; });
  }
  stop_serving(device);
}

bool Cmucam2Connection::has(Cmucam2Role role) const {
  return std::any_of(views_.begin(), views_.end(), [role](const View& view) { return view.role == role; });
}

// ---------------------------------------------------------------- the camera's life

void Cmucam2Connection::start_session(links::ByteLink& link) {
  camera_ = std::make_unique<CmucamCamera>(link, [] { return false; });
  // A CR first ends a stream an earlier session left running.
  camera_->idle();
  camera_->command(cam::poll_mode(true));
  for (Axis& axis : axes_) axis.sent.reset();  // the servos hold what they had; send ours again
  last_step_ = Clock::now();
  next_cycle_ = Clock::now();
}

void Cmucam2Connection::connect(links::ByteLink& link) {
  // A camera just powered takes a moment to boot: asked until kBootTime has passed.
  const auto give_up = Clock::now() + kBootTime;
  for (;;) {
    try {
      start_session(link);
      return;
    } catch (const links::ExchangeError& e) {
      if (Clock::now() >= give_up) {
        throw std::runtime_error(std::string(e.what()) + " (is it powered, at 115200 baud?)");
      }
    }
  }
}

bool Cmucam2Connection::reconnect(links::ByteLink& link, Attempt /*attempt*/, const std::stop_token& stop) {
  if (stop.stop_requested()) return false;
  start_session(link);  // an ExchangeError: silent still, try again later
  return true;
}

void Cmucam2Connection::robot_lost() { camera_.reset(); }

void Cmucam2Connection::stop_motion(links::ByteLink& link) noexcept {
  // The servos hold where they are; the camera is left idle, not streaming.
  try {
    CmucamCamera(link, [] { return false; }).idle();
  } catch (const std::exception& e) {
    logger().warning(label() + ": the camera did not return to idle: " + e.what());
  }
  camera_.reset();
}

std::vector<core::DriverCounter> Cmucam2Connection::protocol_counters() const {
  return {{"t_packets", packets_.load()}, {"refused_commands", refused_.load()}};
}

// ---------------------------------------------------------------- the cycle

void Cmucam2Connection::serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& /*woke*/) {
  std::lock_guard lock(views_mutex_);
  try {
    for (const View& view : views_) {
      if (view.device->pending_requests() > 0) view.device->service_requests();
    }
    take_commands();
    const auto now = Clock::now();
    move_servos(now);
    if (now < next_cycle_) return;
    if (has(Cmucam2Role::blobfinder)) publish_blobs();
    if (has(Cmucam2Role::ptz)) publish_servos();
    // A blobfinder's TCs are paced by the camera's frames.
    next_cycle_ = has(Cmucam2Role::blobfinder) ? Clock::now() : Clock::now() + kServoPeriod;
  } catch (const links::ExchangeError& e) {
    throw hardware_driver::RobotLost(e.what());
  }
}

Cmucam2Connection::Clock::time_point Cmucam2Connection::next_deadline() const {
  std::lock_guard lock(views_mutex_);
  if (views_.empty()) return Clock::time_point::max();
  const bool stepping = std::any_of(axes_.begin(), axes_.end(),
                                    [](const Axis& axis) { return axis.set_point != axis.target; });
  return stepping ? std::min(next_cycle_, last_step_ + kStepPeriod) : next_cycle_;
}

void Cmucam2Connection::serve_while_away() {
  std::lock_guard lock(views_mutex_);
  for (const View& view : views_) {
    if (view.device->pending_requests() > 0) view.device->service_requests();
    (void)view.device->take_command();  // no servo to move: not replayed later
  }
}

void Cmucam2Connection::take_commands() {
  for (const View& view : views_) {
    if (view.role != Cmucam2Role::ptz) continue;
    const auto command = view.device->take_command();
    if (!command) continue;
    const auto ptz = protocol::decode<protocol::PtzCommand>(command->payload);
    const std::array<double, 2> angles{static_cast<double>(ptz.pan), static_cast<double>(ptz.tilt)};
    const std::array<double, 2> speeds{static_cast<double>(ptz.panspeed), static_cast<double>(ptz.tiltspeed)};
    for (std::size_t i = 0; i < axes_.size(); ++i) {
      Axis& axis = axes_[i];
      axis.commanded = true;
      if (velocity_control_) {
        // Toward the end of travel in the speed's direction; 0 holds.
        axis.speed = std::fabs(speeds[i]);
        axis.target = speeds[i] > 0 ? 255 : speeds[i] < 0 ? 0 : static_cast<int>(std::lround(axis.set_point));
        continue;
      }
      axis.target = position_of(angles[i]);
      axis.speed = std::fabs(speeds[i]);
    }
  }
}

void Cmucam2Connection::move_servos(Clock::time_point now) {
  const double seconds = std::chrono::duration<double>(now - last_step_).count();
  last_step_ = now;
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    Axis& axis = axes_[i];
    if (axis.speed == 0) {
      axis.set_point = axis.target;  // the servo's own speed: the unit's default
    } else {
      const double step = axis.speed / settings_.degrees_per_position * seconds;
      const double to_go = axis.target - axis.set_point;
      axis.set_point = std::fabs(to_go) <= step ? axis.target : axis.set_point + std::copysign(step, to_go);
    }
    const int position = static_cast<int>(std::lround(axis.set_point));
    if (!axis.commanded || axis.sent == position) continue;
    try {
      camera_->command(cam::set_servo(static_cast<int>(i), position));
    } catch (const links::ExchangeError& e) {
      if (e.kind() != links::ExchangeFailure::refused) throw;
      ++refused_;
    }
    axis.sent = position;
  }
}

void Cmucam2Connection::publish_blobs() {
  protocol::BlobfinderData data;
  data.width = kFrameWidth;
  data.height = kFrameHeight;
  for (const cam::ColorBounds& color : colors_) {
    const cam::TPacket packet = camera_->track(color);
    ++packets_;
    if (packet.pixels == 0 && packet.mx == 0) continue;  // not in view: no blob
    data.blobs.push_back({.color = color.packed_middle(),
                          .area = static_cast<std::uint32_t>(packet.pixels),
                          .x = static_cast<std::uint16_t>(packet.mx),
                          .y = static_cast<std::uint16_t>(packet.my),
                          .left = static_cast<std::uint16_t>(std::min(packet.x1, packet.x2)),
                          .right = static_cast<std::uint16_t>(std::max(packet.x1, packet.x2)),
                          .top = static_cast<std::uint16_t>(std::min(packet.y1, packet.y2)),
                          .bottom = static_cast<std::uint16_t>(std::max(packet.y1, packet.y2)),
                          .range = 0});
  }
  data.header[0] = {.index = 0, .num = static_cast<std::uint16_t>(data.blobs.size())};
  const auto payload = protocol::encode(data);
  for (const View& view : views_) {
    if (view.role == Cmucam2Role::blobfinder) view.device->publish(payload);
  }
}

void Cmucam2Connection::publish_servos() {
  protocol::PtzData data;
  std::array<std::int16_t*, 2> angles{&data.pan, &data.tilt};
  std::array<std::int16_t*, 2> speeds{&data.panspeed, &data.tiltspeed};
  for (std::size_t i = 0; i < axes_.size(); ++i) {
    const std::string line = camera_->query(cam::get_servo(static_cast<int>(i)),
                                             [](std::string_view text) { return cam::parse_number(text).has_value(); });
    const std::optional<int> position = cam::parse_number(line);
    if (!position) throw hardware_driver::RobotLost("the camera answered GS with '" + line + "'");
    *angles[i] = wire_degrees(degrees_of(*position));
    const bool moving = axes_[i].set_point != axes_[i].target;
    *speeds[i] = moving ? wire_degrees(axes_[i].speed) : 0;
  }
  data.zoom = kFieldOfView;
  const auto payload = protocol::encode(data);
  for (const View& view : views_) {
    if (view.role == Cmucam2Role::ptz) view.device->publish(payload);
  }
}

int Cmucam2Connection::position_of(double degrees) const {
  return std::clamp(kCentre + static_cast<int>(std::lround(degrees / settings_.degrees_per_position)), 0, 255);
}

double Cmucam2Connection::degrees_of(double position) const {
  return (position - kCentre) * settings_.degrees_per_position;
}

// ---------------------------------------------------------------- requests

core::RequestResult Cmucam2Connection::handle_request(Cmucam2Role role, const core::Request& request) {
  if (role == Cmucam2Role::ptz) return interfaces::answer_ptz_request(*this, request);
  return set_color(request);
}

// SET_COLOR: the first colour tracked from now on (1.5 had no blobfinder
// requests: its server answered ERR). The camera has no automatic bounds
// (-1), and IMAGER_PARAMS is not offered.
core::RequestResult Cmucam2Connection::set_color(const core::Request& request) {
  if (request.payload.size() != protocol::BlobfinderColorConfig::kWireSize ||
      request.payload.front() != protocol::kBlobfinderSetColorReq) {
    return core::RequestResult::nack();
  }
  const auto asked = protocol::decode<protocol::BlobfinderColorConfig>(request.payload);
  const cam::ColorBounds bounds{asked.rmin, asked.rmax, asked.gmin, asked.gmax, asked.bmin, asked.bmax};
  if (!bounds.valid()) return core::RequestResult::nack();
  colors_.front() = bounds;
  return core::RequestResult::ack();
}

bool Cmucam2Connection::set_control_mode(std::uint8_t mode) {
  if (mode != protocol::kPtzVelocityControl && mode != protocol::kPtzPositionControl) return false;
  velocity_control_ = mode == protocol::kPtzVelocityControl;
  for (Axis& axis : axes_) {
    // A new mode starts held where the servos are.
    axis.target = static_cast<int>(std::lround(axis.set_point));
    axis.speed = 0;
  }
  return true;
}

}  // namespace playerkit::drivers::cmucam2
