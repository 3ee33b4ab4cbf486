#pragma once
// The interfaces of Player 1.5: wire code, config-file name and default driver
// (wire-format.md §4). The header's codes win over the manual's table: null is 256,
// camera is 40, nomad is 34.

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace playerkit::protocol {

inline constexpr std::uint16_t kPlayerCode = 1;
inline constexpr std::uint16_t kPowerCode = 2;
inline constexpr std::uint16_t kGripperCode = 3;
inline constexpr std::uint16_t kPositionCode = 4;
inline constexpr std::uint16_t kSonarCode = 5;
inline constexpr std::uint16_t kLaserCode = 6;
inline constexpr std::uint16_t kBlobfinderCode = 7;
inline constexpr std::uint16_t kPtzCode = 8;
inline constexpr std::uint16_t kAudioCode = 9;
inline constexpr std::uint16_t kFiducialCode = 10;
inline constexpr std::uint16_t kCommsCode = 11;
inline constexpr std::uint16_t kSpeechCode = 12;
inline constexpr std::uint16_t kGpsCode = 13;
inline constexpr std::uint16_t kBumperCode = 14;
inline constexpr std::uint16_t kTruthCode = 15;
inline constexpr std::uint16_t kIdarturretCode = 16;
inline constexpr std::uint16_t kIdarCode = 17;
inline constexpr std::uint16_t kDescartesCode = 18;
inline constexpr std::uint16_t kDioCode = 20;
inline constexpr std::uint16_t kAioCode = 21;
inline constexpr std::uint16_t kIrCode = 22;
inline constexpr std::uint16_t kWifiCode = 23;
inline constexpr std::uint16_t kWaveformCode = 24;
inline constexpr std::uint16_t kLocalizeCode = 25;
inline constexpr std::uint16_t kMcomCode = 26;
inline constexpr std::uint16_t kSoundCode = 27;
inline constexpr std::uint16_t kAudiodspCode = 28;
inline constexpr std::uint16_t kAudiomixerCode = 29;
inline constexpr std::uint16_t kPosition3dCode = 30;
inline constexpr std::uint16_t kSimulationCode = 31;
inline constexpr std::uint16_t kServiceAdvCode = 32;
inline constexpr std::uint16_t kBlinkenlightCode = 33;
inline constexpr std::uint16_t kNomadCode = 34;
inline constexpr std::uint16_t kCameraCode = 40;
inline constexpr std::uint16_t kNullCode = 256;

struct InterfaceInfo {
  std::uint16_t code;
  std::string_view name;            // as written in config files: "laser"
  std::string_view constant;        // as in player.h: "PLAYER_LASER_CODE"
  std::string_view default_driver;  // empty: cannot be declared in a config file
};

// Every interface, in code order.
std::span<const InterfaceInfo> all_interfaces();
const InterfaceInfo* find_interface(std::string_view name);
const InterfaceInfo* find_interface(std::uint16_t code);

// "laser" for 6; "interface 99" for a code Player 1.5 does not define.
std::string interface_name(std::uint16_t code);

}  // namespace playerkit::protocol
