#include "families/amtecpowercube/emulator/powercube_emulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "families/amtecpowercube/protocol/powercube_units.hpp"

namespace playerkit::emulators {

namespace pc = hardware::powercube;
using namespace std::chrono_literals;

namespace {

// Motion is integrated in steps this long: fine enough that a stop lands
// within a micro-radian of its target.
constexpr Duration kIntegrationStep = 1ms;
// While a module moves, the runner lets time pass this often (tests read
// the state between requests).
constexpr Duration kMotionTick = 20ms;

void check(bool holds, const std::string& what) {
  if (!holds) throw std::invalid_argument("amtecpowercube emulator: " + what);
}

double toward(double value, double wanted, double most) {
  return value + std::clamp(wanted - value, -most, most);
}

}  // namespace

PowercubeEmulator::PowercubeEmulator(PowercubeEmulatorOptions options)
    : options_(options),
      max_speed_(pc::radians(options.max_speed)),
      acceleration_(pc::radians(options.acceleration)) {
  check(options_.max_speed > 0 && options_.acceleration > 0, "the top speed and the acceleration must be above 0");
  check(options_.pan_min < 0 && options_.pan_max > 0, "the pan limits must lie below and above 0 (the home)");
  check(options_.tilt_min < 0 && options_.tilt_max > 0, "the tilt limits must lie below and above 0 (the home)");
  check(options_.pan_start >= options_.pan_min && options_.pan_start <= options_.pan_max,
        "the pan start must lie within the pan limits");
  check(options_.tilt_start >= options_.tilt_min && options_.tilt_start <= options_.tilt_max,
        "the tilt start must lie within the tilt limits");
  check(options_.pan_present || options_.tilt_present, "at least one module must be on the line");
  axis(Module::pan) = {.present = options_.pan_present,
                       .position = pc::radians(options_.pan_start),
                       .min = pc::radians(options_.pan_min),
                       .max = pc::radians(options_.pan_max)};
  axis(Module::tilt) = {.present = options_.tilt_present,
                        .position = pc::radians(options_.tilt_start),
                        .min = pc::radians(options_.tilt_min),
                        .max = pc::radians(options_.tilt_max)};
}

PowercubeEmulator::Axis* PowercubeEmulator::axis_with_id(std::uint8_t id) {
  for (const Module module : {Module::pan, Module::tilt}) {
    if (id == static_cast<std::uint8_t>(module) && axis(module).present) return &axis(module);
  }
  return nullptr;
}

void PowercubeEmulator::receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) {
  advance(now);  // replies report where the modules are now
  if (host_baud != 0 && host_baud != kBaud) {
    // At another speed the UART sees noise: whatever was half received is lost too.
    received_.clear();
    return;
  }
  received_.insert(received_.end(), bytes.begin(), bytes.end());
  const framing::DleStuffedFormat format(pc::frame_options());
  while (!received_.empty()) {
    const auto scan = format.scan(received_);
    if (scan.kind == framing::FrameScan::Kind::need_more) break;
    if (scan.kind == framing::FrameScan::Kind::frame) handle(std::span(received_).first(scan.length));
    received_.erase(received_.begin(), received_.begin() + static_cast<long>(scan.length));
  }
}

void PowercubeEmulator::handle(std::span<const std::uint8_t> telegram) {
  const auto frame = pc::decode(telegram);
  if (!frame || frame->data.empty()) return;
  if (!pc::check_holds(*frame)) {
    ++bad_checks_;  // the module drops it: the host hears nothing
    return;
  }
  Axis* addressed = axis_with_id(frame->module);
  if (addressed == nullptr) return;  // no such module on the line
  ++frames_;
  const std::vector<std::uint8_t> reply = execute(*addressed, frame->data);
  output_.push_back({pc::encode(frame->module, reply), true});
}

std::vector<std::uint8_t> PowercubeEmulator::execute(Axis& axis, const std::vector<std::uint8_t>& data) {
  const auto code = static_cast<pc::CommandCode>(data[0]);
  switch (code) {
    case pc::CommandCode::reset:
      axis.state &= ~(pc::state_bit::error | pc::state_bit::halted);
      break;
    case pc::CommandCode::home:
      if ((axis.state & pc::state_bit::error) == 0) {
        axis.state &= ~(pc::state_bit::homed | pc::state_bit::halted);
        axis.motion = Motion::homing;
        axis.target = 0;
        axis.cruise = max_speed_;
        ++axis.homings;
      }
      break;
    case pc::CommandCode::halt:
      axis.motion = Motion::idle;
      axis.velocity = 0;
      axis.state |= pc::state_bit::halted;
      break;
    case pc::CommandCode::get_extended: {
      if (data.size() < 2) break;
      const auto parameter = static_cast<pc::Parameter>(data[1]);
      std::uint32_t raw = 0;
      switch (parameter) {
        case pc::Parameter::position: raw = pc::float_bits(static_cast<float>(axis.position)); break;
        case pc::Parameter::velocity: raw = pc::float_bits(static_cast<float>(axis.velocity)); break;
        case pc::Parameter::state: raw = axis.state; break;
        case pc::Parameter::min_position: raw = pc::float_bits(static_cast<float>(axis.min)); break;
        case pc::Parameter::max_position: raw = pc::float_bits(static_cast<float>(axis.max)); break;
        default: break;  // a parameter not modelled reads 0
      }
      return pc::value_reply_data(parameter, raw);
    }
    case pc::CommandCode::set_extended:
      if (data.size() >= 6 && data[1] == static_cast<std::uint8_t>(pc::Parameter::min_position)) {
        axis.min = std::min(0.0, static_cast<double>(pc::float_from_bits(pc::read_u32(std::span(data).subspan(2, 4)))));
      } else if (data.size() >= 6 && data[1] == static_cast<std::uint8_t>(pc::Parameter::max_position)) {
        axis.max = std::max(0.0, static_cast<double>(pc::float_from_bits(pc::read_u32(std::span(data).subspan(2, 4)))));
      }
      break;
    case pc::CommandCode::set_motion:
      start_motion(axis, data);
      break;
  }
  // Commands other than GET are answered with their code (the driver reads no more of it).
  return {data[0]};
}

void PowercubeEmulator::start_motion(Axis& axis, const std::vector<std::uint8_t>& data) {
  // A module moves only homed and free of a halt or an error.
  if ((axis.state & (pc::state_bit::error | pc::state_bit::halted)) != 0 || (axis.state & pc::state_bit::homed) == 0) {
    return;
  }
  if (data.size() >= 8 && data[1] == static_cast<std::uint8_t>(pc::MotionMode::step)) {
    axis.target = std::clamp(static_cast<double>(pc::float_from_bits(pc::read_u32(std::span(data).subspan(2, 4)))),
                             axis.min, axis.max);
    axis.step_time = data[6] | data[7] << 8;
    const double seconds = axis.step_time / 1000.0;
    const double distance = std::fabs(axis.target - axis.position);
    // The speed of a trapezoid from rest that covers `distance` in `seconds`;
    // a step too short for it goes flat out and arrives late.
    const double discriminant = acceleration_ * acceleration_ * seconds * seconds - 4 * acceleration_ * distance;
    axis.cruise = seconds > 0 && discriminant >= 0
                      ? std::min(max_speed_, (acceleration_ * seconds - std::sqrt(discriminant)) / 2)
                      : max_speed_;
    axis.motion = Motion::step;
  } else if (data.size() >= 6 && data[1] == static_cast<std::uint8_t>(pc::MotionMode::velocity)) {
    axis.target = std::clamp(static_cast<double>(pc::float_from_bits(pc::read_u32(std::span(data).subspan(2, 4)))),
                             -max_speed_, max_speed_);
    axis.motion = Motion::velocity;
  }
}

void PowercubeEmulator::step(Axis& axis, double seconds) const {
  const double most = acceleration_ * seconds;
  switch (axis.motion) {
    case Motion::idle:
      axis.velocity = 0;
      return;
    case Motion::velocity:
      axis.velocity = toward(axis.velocity, axis.target, most);
      break;
    case Motion::step:
    case Motion::homing: {
      const double remaining = axis.target - axis.position;
      if (std::fabs(remaining) <= std::max(std::fabs(axis.velocity) * seconds, 1e-9)) {
        axis.position = axis.target;
        axis.velocity = 0;
        if (axis.motion == Motion::homing) axis.state |= pc::state_bit::homed;
        axis.motion = Motion::idle;
        return;
      }
      // As fast as the cruise allows while it can still brake in time.
      const double wanted = std::copysign(std::min(axis.cruise, std::sqrt(2 * acceleration_ * std::fabs(remaining))),
                                          remaining);
      axis.velocity = toward(axis.velocity, wanted, most);
      break;
    }
  }
  axis.position += axis.velocity * seconds;
  if (axis.position < axis.min || axis.position > axis.max) {
    axis.position = std::clamp(axis.position, axis.min, axis.max);
    axis.velocity = 0;  // against the limit
  }
}

void PowercubeEmulator::advance(Duration now) {
  if (now <= now_) return;
  if (!moving()) {
    for (Axis& a : axes_) a.velocity = 0;
    now_ = now;
    return;
  }
  while (now_ < now) {
    const Duration slice = std::min(kIntegrationStep, now - now_);
    const double seconds = std::chrono::duration<double>(slice).count();
    for (Axis& a : axes_) step(a, seconds);
    now_ += slice;
  }
}

bool PowercubeEmulator::moving() const {
  return std::any_of(axes_.begin(), axes_.end(), [](const Axis& a) {
    switch (a.motion) {
      case Motion::idle: return false;
      case Motion::velocity:
        if (a.velocity == 0 && a.target == 0) return false;
        // Pinned against the limit it is driven into.
        return !((a.target >= 0 && a.position >= a.max) || (a.target <= 0 && a.position <= a.min)) || a.velocity != 0;
      default: return true;
    }
  });
}

Duration PowercubeEmulator::next_deadline() const { return moving() ? now_ + kMotionTick : Duration::max(); }

std::vector<Telegram> PowercubeEmulator::take_output() { return std::exchange(output_, {}); }

void PowercubeEmulator::raise_error(Module module) {
  Axis& a = axis(module);
  a.motion = Motion::idle;
  a.velocity = 0;
  a.state |= pc::state_bit::error;
}

std::string PowercubeEmulator::describe() const {
  const auto module_text = [](const Axis& a) {
    char text[64];
    std::snprintf(text, sizeof text, "%.2f deg%s%s%s", pc::degrees(a.position),
                  (a.state & pc::state_bit::homed) != 0 ? ", homed" : ", not homed",
                  (a.state & pc::state_bit::halted) != 0 ? ", halted" : "",
                  (a.state & pc::state_bit::error) != 0 ? ", ERROR" : "");
    return a.present ? std::string(text) : std::string("absent");
  };
  return "PowerCube wrist, pan (12) " + module_text(axes_[0]) + ", tilt (11) " + module_text(axes_[1]) +
         (moving() ? ", moving" : "");
}

}  // namespace playerkit::emulators
