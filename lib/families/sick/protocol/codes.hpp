#pragma once
// The numbers of the SICK LMS 2xx / PLS telegram protocol: command and reply
// codes, the 0x20 "switch mode" parameter (operating modes and baud rates),
// passwords, measuring units and modes, and the LMS 200 scan variants.
// Sources: sicklms200.md §1-2 and §6, sickpls.md §1-2.

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace playerkit::hardware::sick {

enum class Model { lms200, pls };

// T1's password; what the device answers A0 00 to (A0 01 otherwise).
constexpr std::string_view installation_password(Model model) {
  return model == Model::lms200 ? "SICK_LMS" : "SICK_PLS";
}
inline constexpr std::size_t kPasswordLength = 8;

// Host commands (body[0]).
inline constexpr std::uint8_t kSwitchModeCommand = 0x20;
inline constexpr std::uint8_t kGetTypeCommand = 0x3A;
inline constexpr std::uint8_t kSetVariantCommand = 0x3B;
inline constexpr std::uint8_t kGetConfigCommand = 0x74;
inline constexpr std::uint8_t kSetConfigCommand = 0x77;

// Device replies (body[0]): the command + 0x80, the scans, or the refusal.
inline constexpr std::uint8_t kSwitchModeReply = 0xA0;
inline constexpr std::uint8_t kTypeReply = 0xBA;
inline constexpr std::uint8_t kVariantReply = 0xBB;
inline constexpr std::uint8_t kConfigReply = 0xF4;
inline constexpr std::uint8_t kSetConfigReply = 0xF7;
inline constexpr std::uint8_t kScanReply = 0xB0;          // all values
inline constexpr std::uint8_t kSubrangeScanReply = 0xB7;  // values first..last
inline constexpr std::uint8_t kNotAcknowledged = 0x92;    // unknown or refused command

// The 0x20 command's parameter (body[1]).
inline constexpr std::uint8_t kInstallationMode = 0x00;   // + 8-byte password
inline constexpr std::uint8_t kStreamAllMode = 0x24;      // continuous B0
inline constexpr std::uint8_t kRequestValuesMode = 0x25;  // power-up: data on request only
inline constexpr std::uint8_t kStreamSubrangeMode = 0x27; // continuous B7, + first, last

// Baud-rate selection, also a 0x20 parameter. 19200 is never sent by the
// Player drivers and is not in sickpls.md's list; sicktoolbox knows it for
// both devices.
std::optional<std::uint8_t> baud_code(int baud);
std::optional<int> baud_of_code(std::uint8_t code);
inline constexpr std::array<int, 4> kBaudRates = {9600, 19200, 38400, 500000};

// Block E of the configuration, and the unit bits (14-15) of a scan's count
// word. sicklms200 sends 0x02 for range_res 100, which sicktoolbox does not
// list; such values are carried through as they are.
enum class Unit : std::uint8_t { centimetre = 0x00, millimetre = 0x01 };
// Metres per distance step, nullopt for a code not listed.
std::optional<double> metres_per_step(Unit unit);

// Block D of the configuration: what bits 13-15 of each value carry.
enum class MeasuringMode : std::uint8_t {
  fields_and_dazzle = 0x00,  // 8/80 m, field A, B and dazzle flags
  reflector_levels = 0x01,   // 8/80 m, reflector level 0-7
};

// Field of view and angular step of an LMS 200 scan (command 0x3B). The PLS
// has one, 180 deg at 0.5 deg.
struct Variant {
  std::uint16_t width_deg = 180;
  std::uint16_t resolution_cdeg = 50;  // hundredths of a degree: 25, 50, 100

  // One of the five an LMS 200 accepts: 180 at 0.5/1 deg, 100 at 0.25/0.5/1 deg.
  [[nodiscard]] bool supported() const;
  // Values in a full scan: 181/361 for 180 deg, 101/201/401 for 100 deg.
  // Only meaningful for a supported variant (0 for a zero resolution).
  [[nodiscard]] int value_count() const {
    return resolution_cdeg == 0 ? 0 : width_deg * 100 / resolution_cdeg + 1;
  }
  // Value i (0-based) looks at first_angle + i * step in the laser frame,
  // counter-clockwise from -width/2 (the scanner's right) to +width/2.
  [[nodiscard]] double first_angle_rad() const;
  [[nodiscard]] double step_rad() const;

  friend bool operator==(const Variant&, const Variant&) = default;
};

inline constexpr std::array<Variant, 5> kLms200Variants = {
    Variant{180, 50}, Variant{180, 100}, Variant{100, 25}, Variant{100, 50}, Variant{100, 100}};
inline constexpr Variant kPlsVariant{180, 50};

}  // namespace playerkit::hardware::sick
