#include "families/p2os/driver/cmucam_commands.hpp"

#include <array>

namespace playerkit::drivers::p2os {

namespace hw = hardware::p2os;

namespace {

hw::Command text_command(std::string_view text) {
  return hw::Command::with_string(hw::command::tty3, std::string(text));
}

// GETAUX2's largest useful request: one whole 10-byte message is sure to be
// inside 19 bytes, wherever the camera's output happens to start.
constexpr int kAux2ReadSize = 19;

}  // namespace

hw::Command cmucam_stop_command() { return text_command("\r"); }

std::vector<hw::Command> cmucam_reset_commands() {
  return {cmucam_stop_command(), text_command("RS\r"), text_command("RM 3\r"),
          hw::Command::with_integer(hw::command::getaux2, 0)};
}

std::vector<hw::Command> cmucam_track_commands(std::string_view tracking_text) {
  return {cmucam_stop_command(), text_command(tracking_text),
          hw::Command::with_integer(hw::command::getaux2, kAux2ReadSize)};
}

std::vector<hw::Command> cmucam_poll_commands() {
  return {hw::Command::with_integer(hw::command::getaux2, 0),
          hw::Command::with_integer(hw::command::getaux2, kAux2ReadSize)};
}

std::string tracking_text(const protocol::BlobfinderColorConfig& color) {
  const std::array<int, 6> bounds{color.rmin, color.rmax, color.gmin, color.gmax, color.bmin, color.bmax};
  std::string text = "TC";
  for (int bound : bounds) {
    if (bound < 0) return "TW\r";
    text += " " + std::to_string(bound);
  }
  return text + "\r";
}

std::optional<std::string> imager_text(const protocol::BlobfinderImagerConfig& imager) {
  std::string pairs;
  if (imager.brightness >= 0 && imager.brightness <= 255) pairs += " 6 " + std::to_string(imager.brightness);
  if (imager.contrast >= 0 && imager.contrast <= 255) pairs += " 5 " + std::to_string(imager.contrast);
  if (imager.autogain == 0 || imager.autogain == 1) pairs += imager.autogain == 1 ? " 19 33" : " 19 32";
  // Register 18 values for colour modes 0 ... 3.
  static constexpr std::array<int, 4> kColorModeValues{40, 44, 32, 36};
  if (imager.colormode >= 0 && imager.colormode <= 3) {
    pairs += " 18 " + std::to_string(kColorModeValues[static_cast<std::size_t>(imager.colormode)]);
  }
  if (pairs.empty()) return std::nullopt;
  return "CR " + pairs + "\r";
}

}  // namespace playerkit::drivers::p2os
