#include "families/sick/emulator/sick_laser_emulator.hpp"

#include "families/sick/protocol/frame_format.hpp"
#include "families/sick/protocol/replies.hpp"
#include "families/sick/protocol/scan.hpp"
#include "families/sick/protocol/telegram.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

namespace playerkit::emulators {
namespace sick = hardware::sick;
namespace {

constexpr std::size_t kTypeTextLength = 20;

template <class... Visitors>
struct Overloaded : Visitors... {
  using Visitors::operator()...;
};
template <class... Visitors>
Overloaded(Visitors...) -> Overloaded<Visitors...>;

std::string padded_type(const SickEmulatorOptions& options) {
  std::string text = options.type.value_or("LMS200;30106");
  if (text.size() > kTypeTextLength) {
    throw std::invalid_argument("SICK emulator: type text \"" + text + "\" is over 20 characters");
  }
  text.resize(kTypeTextLength, ' ');
  return text;
}

sick::ConfigBlock power_up_config() {
  sick::ConfigBlock config;
  config.set_measuring_mode(sick::MeasuringMode::fields_and_dazzle);
  config.set_unit(sick::Unit::millimetre);
  return config;
}

bool known_unit(sick::Unit unit) { return sick::metres_per_step(unit).has_value(); }

bool known_measuring_mode(sick::MeasuringMode mode) {
  return mode == sick::MeasuringMode::fields_and_dazzle ||
         mode == sick::MeasuringMode::reflector_levels;
}

const char* mode_name(SickLaserEmulator::Mode mode) {
  switch (mode) {
    case SickLaserEmulator::Mode::idle: return "idle";
    case SickLaserEmulator::Mode::installation: return "installation mode";
    case SickLaserEmulator::Mode::streaming_all: return "streaming B0";
    case SickLaserEmulator::Mode::streaming_subrange: return "streaming B7";
  }
  return "?";
}

}  // namespace

SickLaserEmulator::SickLaserEmulator(const SickModelProfile& profile, SickEmulatorOptions options)
    : profile_(profile),
      options_(std::move(options)),
      scene_(options_),
      type_text_(padded_type(options_)),
      baud_(options_.power_up_baud),
      variant_(sick::Variant{180, 50}),  // both devices power up at 180 deg, 0.5 deg
      config_(power_up_config()) {
  if (!sick::baud_code(baud_)) {
    throw std::invalid_argument("SICK emulator: no rate code for a power-up speed of " +
                                std::to_string(baud_) + " baud");
  }
  if (options_.max_range_m && !(*options_.max_range_m > 0.0)) {
    throw std::invalid_argument("SICK emulator: max range must be positive");
  }
  // The map was read into the scene; the pointer must not be used again.
  options_.map = nullptr;
}

sick::Unit SickLaserEmulator::unit() const {
  return profile_.configurable ? config_.unit() : sick::Unit::centimetre;
}

double SickLaserEmulator::max_range_m() const {
  const double full_scale = sick::kMaxDistance * sick::metres_per_step(unit()).value_or(0.001);
  return std::min(options_.max_range_m.value_or(full_scale), full_scale);
}

Duration SickLaserEmulator::line_time(std::size_t bytes) const {
  const auto bits = static_cast<std::int64_t>(bytes) * profile_.bits_per_byte;
  // Rounded up: the pacing must never outrun the line.
  return Duration((bits * 1'000'000'000 + baud_ - 1) / baud_);
}

std::size_t SickLaserEmulator::stream_telegram_size() const {
  return mode_ == Mode::streaming_subrange
             ? sick::subrange_scan_telegram_size(static_cast<std::size_t>(subrange_.count()))
             : sick::scan_telegram_size(static_cast<std::size_t>(variant_.value_count()));
}

Duration SickLaserEmulator::scan_period() const {
  return std::max(profile_.rotation_period, line_time(stream_telegram_size()));
}

void SickLaserEmulator::receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) {
  if (options_.model_baud_rates && host_baud != 0 && host_baud != baud_) {
    // Framing errors at the device's speed: whatever was arriving is lost too.
    noise_bytes_ += bytes.size() + received_.size();
    received_.clear();
    return;
  }
  if (!received_.empty() && now - last_byte_ > kInterByteTimeout) received_.clear();
  if (bytes.empty()) return;
  last_byte_ = now;
  received_.insert(received_.end(), bytes.begin(), bytes.end());

  static const auto format = sick::SickFrameFormat::requests();
  std::size_t used = 0;
  while (used < received_.size()) {
    const auto rest = std::span<const std::uint8_t>(received_).subspan(used);
    const framing::FrameScan scan = format.scan(rest);
    if (scan.kind == framing::FrameScan::Kind::need_more) break;
    if (scan.kind == framing::FrameScan::Kind::frame) {
      handle_telegram(rest.first(scan.length), now);
    } else if (scan.kind == framing::FrameScan::Kind::bad_checksum) {
      output_.push_back({{sick::kNak}, false});
    } else {
      noise_bytes_ += scan.length;
    }
    used += scan.length;
  }
  received_.erase(received_.begin(), received_.begin() + static_cast<std::ptrdiff_t>(used));
}

void SickLaserEmulator::handle_telegram(std::span<const std::uint8_t> telegram, Duration now) {
  // Whatever it asks, the stream stops first (sicklms200.md §6 point 10).
  if (streaming()) mode_ = Mode::idle;
  std::vector<std::uint8_t> reply;
  try {
    reply = answer(sick::decode_request(sick::unframe_request(telegram)), now);
  } catch (const sick::TelegramError&) {
    reply = sick::encode_reply(sick::NotAcknowledgedReply{});
  }
  send(std::move(reply));
  ++requests_answered_;
}

std::vector<std::uint8_t> SickLaserEmulator::answer(const sick::Request& request, Duration now) {
  const auto refuse = [] { return sick::encode_reply(sick::NotAcknowledgedReply{}); };
  return std::visit(
      Overloaded{
          [&](const sick::InstallationModeRequest& r) {
            if (r.password != sick::installation_password(profile_.model)) {
              return sick::encode_reply(sick::ModeReply{sick::ModeResult::wrong_password});
            }
            mode_ = Mode::installation;
            return sick::encode_reply(sick::ModeReply{});
          },
          [&](const sick::BaudRateRequest& r) {
            // Answered at the old speed: the reply is queued before the switch.
            auto reply = sick::encode_reply(sick::ModeReply{});
            baud_ = r.baud;
            return reply;
          },
          [&](const sick::GetTypeRequest&) {
            if (!profile_.configurable) return refuse();
            return sick::encode_reply(sick::TypeReply{type_text_});
          },
          [&](const sick::SetVariantRequest& r) {
            if (!profile_.configurable) return refuse();
            const bool accepted = r.variant.supported();
            if (accepted) variant_ = r.variant;
            return sick::encode_reply(sick::VariantReply{accepted, variant_});
          },
          [&](const sick::GetConfigRequest&) {
            if (!profile_.configurable) return refuse();
            return sick::encode_reply(sick::ConfigReply{config_});
          },
          [&](const sick::SetConfigRequest& r) {
            if (!profile_.configurable) return refuse();
            return set_configuration(r.config);
          },
          [&](const sick::StreamAllRequest&) {
            return start_stream(Mode::streaming_all, {}, now);
          },
          [&](const sick::StreamSubrangeRequest& r) {
            const int count = variant_.value_count();
            if (r.range.first < 1 || r.range.count() == 0 || r.range.last > count) return refuse();
            return start_stream(Mode::streaming_subrange, r.range, now);
          },
          [&](const sick::OtherRequest&) { return refuse(); },
      },
      request);
}

std::vector<std::uint8_t> SickLaserEmulator::set_configuration(const sick::ConfigBlock& requested) {
  // The configuration is written in installation mode only, and only with a
  // measuring mode and unit this emulator can produce; otherwise F7 00 and
  // the configuration in force.
  const bool accepted = mode_ == Mode::installation && known_unit(requested.unit()) &&
                        known_measuring_mode(requested.measuring_mode());
  if (accepted) config_ = requested;
  return sick::encode_reply(sick::SetConfigReply{accepted, config_});
}

std::vector<std::uint8_t> SickLaserEmulator::start_stream(Mode mode, sick::Subrange range,
                                                          Duration now) {
  mode_ = mode;
  subrange_ = range;
  auto reply = sick::encode_reply(sick::ModeReply{});
  // The first scan follows the reply on the line and a whole rotation.
  const std::size_t reply_bytes = reply.size() + (options_.send_ack ? 1 : 0);
  next_scan_ = now + line_time(reply_bytes) + profile_.rotation_period;
  return reply;
}

void SickLaserEmulator::send(std::vector<std::uint8_t> reply) {
  if (options_.send_ack) output_.push_back({{sick::kAck}, false});
  output_.push_back({std::move(reply), true});
}

void SickLaserEmulator::advance(Duration now) {
  if (!received_.empty() && now - last_byte_ > kInterByteTimeout) received_.clear();
  // A request still arriving holds the stream back: the host takes the
  // next telegram after its request as the answer.
  if (!streaming() || !received_.empty() || now < next_scan_) return;
  send_scan(now);
  const Duration period = scan_period();
  next_scan_ += period;
  // Late by more than a period (a slow runner): the missed scans are gone,
  // as the mirror does not wait, and no burst follows.
  if (next_scan_ <= now) next_scan_ = now + period;
}

void SickLaserEmulator::send_scan(Duration /*now*/) {
  const geometry::Pose2 pose = options_.pose_source ? options_.pose_source() : options_.pose;
  const sick::Unit value_unit = unit();
  const double step_m = sick::metres_per_step(value_unit).value_or(0.001);
  const double max_range = max_range_m();
  const bool reflector_bits = profile_.configurable &&
                              config_.measuring_mode() == sick::MeasuringMode::reflector_levels;

  sick::Scan scan;
  scan.unit = value_unit;
  int first = 0;
  int count = variant_.value_count();
  if (mode_ == Mode::streaming_subrange) {
    scan.subrange = subrange_;
    first = subrange_.first - 1;
    count = subrange_.count();
  }
  scan.values.reserve(static_cast<std::size_t>(count));
  const Eigen::Vector2d origin = pose.translation();
  const double first_angle = pose.yaw + variant_.first_angle_rad();
  const double step_angle = variant_.step_rad();
  for (int i = first; i < first + count; ++i) {
    const SickBeamReading reading = scene_.measure(origin, first_angle + i * step_angle, max_range);
    const double steps = std::round(reading.range_m / step_m);
    const auto distance =
        static_cast<std::uint16_t>(std::clamp(steps, 0.0, double{sick::kMaxDistance}));
    scan.values.push_back(sick::make_value(distance, reflector_bits ? reading.reflector_level : 0));
  }
  output_.push_back({sick::encode_scan(scan), true});
  ++scans_sent_;
}

Duration SickLaserEmulator::next_deadline() const {
  if (!received_.empty()) return last_byte_ + kInterByteTimeout + Duration(1);
  return streaming() ? next_scan_ : Duration::max();
}

std::vector<Telegram> SickLaserEmulator::take_output() { return std::exchange(output_, {}); }

void SickLaserEmulator::host_disconnected(Duration /*now*/) {
  // The real device notices nothing and keeps streaming; only a request the
  // host was halfway through writing is gone.
  received_.clear();
}

std::string SickLaserEmulator::describe() const {
  std::string text = std::string(profile_.display_name);
  if (profile_.configurable) {
    const auto end = type_text_.find_last_not_of(' ');
    text += " (" + type_text_.substr(0, end == std::string::npos ? 0 : end + 1) + ")";
  }
  text += ", " + std::to_string(baud_) + " baud, " + mode_name(mode_);
  if (streaming()) {
    const int count = mode_ == Mode::streaming_subrange ? subrange_.count() : variant_.value_count();
    text += " " + std::to_string(count) + " values in " +
            (unit() == sick::Unit::centimetre ? "cm" : "mm");
  }
  text += ", " + std::to_string(variant_.width_deg) + " deg at " +
          std::to_string(variant_.resolution_cdeg) + "/100 deg";
  return text;
}

}  // namespace playerkit::emulators
