#include "drive.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

namespace playerkit::player_view {
namespace {

// -1, 0 or 1; a page cannot ask for more than the configured speed.
double unit(const nlohmann::json& value) {
  if (!value.is_number()) return 0.0;
  const double number = value.get<double>();
  if (!std::isfinite(number)) return 0.0;
  return std::clamp(number, -1.0, 1.0);
}

}  // namespace

void DriveControl::message(std::uint64_t page, std::string_view text, double now) {
  const auto json = nlohmann::json::parse(text, nullptr, false);
  if (!json.is_object() || !json.contains("type") || !json["type"].is_string()) return;
  const auto type = json["type"].get<std::string>();
  if (type == "stop") {
    // Any page may stop the robot; only the driving page's stop ends its turn.
    stop();
    return;
  }
  if (type == "motors") {
    if (!json.contains("on") || !json["on"].is_boolean()) return;
    motor_request_ = json["on"].get<bool>();
    if (!*motor_request_) stop();
    return;
  }
  if (type != "drive") return;
  const DriveCommand command{speed_ * unit(json.value("x", nlohmann::json())),
                             turn_rate_ * unit(json.value("yaw", nlohmann::json()))};
  if (command == DriveCommand{}) {
    if (!driver_ || *driver_ == page) stop();
    return;
  }
  // The newest page to press a key drives.
  driver_ = page;
  last_heard_ = now;
  wanted_ = command;
}

void DriveControl::closed(std::uint64_t page) {
  if (driver_ && *driver_ == page) stop();
}

std::optional<DriveCommand> DriveControl::update(double now) {
  if (driver_ && now - last_heard_ > hold_) stop();
  if (wanted_ == sent_) return std::nullopt;
  sent_ = wanted_;
  return sent_;
}

}  // namespace playerkit::player_view
