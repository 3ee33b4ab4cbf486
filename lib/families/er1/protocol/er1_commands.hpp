#pragma once
// The ER1 Robot Control Module's commands as bytes (er1.md §1.1, §2): what
// Player 1.5's er1_position sent, reverse-engineered by its author. A command
// is [motor, checksum, 0, opcode, 0/2/4 argument bytes big-endian] with the
// checksum making the sum of all its bytes 0 modulo 256; the RCM answers each
// with a fixed number of bytes that depends on the opcode alone.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace playerkit::hardware::er1 {

using Bytes = std::vector<std::uint8_t>;

// The RCM's two motor ports.
enum class Motor : std::uint8_t { port0 = 0, port1 = 1 };

// The opcodes 1.5 used (their meaning is only partly known, er1.md §2).
namespace opcode {
inline constexpr std::uint8_t init = 0x8F;
inline constexpr std::uint8_t reset_position = 0x39;  // RESET_1, STOP_8
inline constexpr std::uint8_t execute = 0x1A;
inline constexpr std::uint8_t read_position = 0x1D;
inline constexpr std::uint8_t read_status = 0x31;     // SPEED_1, ACCL_1
inline constexpr std::uint8_t velocity = 0x11;        // SPEED value, RESET_5
inline constexpr std::uint8_t profile = 0x34;         // SPEED_2, ACCL_2, STOP_1
inline constexpr std::uint8_t mode_77 = 0x77;
inline constexpr std::uint8_t mode_80 = 0x80;
inline constexpr std::uint8_t mode_a0 = 0xA0;
inline constexpr std::uint8_t mode_d0 = 0xD0;
inline constexpr std::uint8_t acceleration = 0x90;    // SPEED_6, ACCL_3, RESET_6
inline constexpr std::uint8_t deceleration = 0x91;    // RESET_7
inline constexpr std::uint8_t voltage = 0xEF;
}  // namespace opcode

// Length of a whole command with this opcode: 4, 6 or 8; 0 for an opcode the
// RCM is not known to take.
[[nodiscard]] std::size_t command_length(std::uint8_t op);
// Bytes the RCM answers a command with: 6 (INIT, position), 4 (status,
// voltage) or 2.
[[nodiscard]] std::size_t reply_length(std::uint8_t op);

// The byte that makes the sum of `bytes` and itself 0 modulo 256.
[[nodiscard]] std::uint8_t balancing_byte(std::span<const std::uint8_t> bytes);
[[nodiscard]] bool sums_to_zero(std::span<const std::uint8_t> bytes);

// A command with its checksum; `argument` holds 0, 2 or 4 bytes.
[[nodiscard]] Bytes command(Motor motor, std::uint8_t op, std::span<const std::uint8_t> argument = {});
[[nodiscard]] Bytes command16(Motor motor, std::uint8_t op, std::uint16_t argument);
[[nodiscard]] Bytes command32(Motor motor, std::uint8_t op, std::int32_t argument);

// The commands by the names of er1.md §2.
[[nodiscard]] Bytes init(Motor motor);
[[nodiscard]] Bytes execute(Motor motor);
[[nodiscard]] Bytes read_position(Motor motor);
[[nodiscard]] Bytes set_velocity(Motor motor, std::int32_t speed_register);
// RESET_1 ... RESET_7, EXECUTE: the odometry reset after INIT.
[[nodiscard]] std::vector<Bytes> reset_sequence(Motor motor);
// SPEED_1 and then SPEED_2..4 from standstill or ACCL_2 when moving, the
// value, SPEED_6 (EXECUTE follows once both motors are set).
[[nodiscard]] std::vector<Bytes> speed_sequence(Motor motor, std::int32_t speed_register, bool from_standstill);
// ACCL_1, ACCL_2, ACCL_3 (with its checksum right: 1.5 sent 0xF2, er1.md §5.2).
[[nodiscard]] std::vector<Bytes> acceleration_sequence(Motor motor);
// STOP_1 ... STOP_7, EXECUTE, STOP_8.
[[nodiscard]] std::vector<Bytes> stop_sequence(Motor motor);

// The RCM's speed register for a wheel speed: trunc(cm/s x 16819.8).
inline constexpr double kSpeedUnitsPerCentimetrePerSecond = 16819.8;
// One encoder tick: 0.00602836879 mm.
inline constexpr double kMillimetresPerTick = 0.00602836879;
[[nodiscard]] std::int32_t speed_register(double millimetres_per_second);
[[nodiscard]] double millimetres_per_second(std::int32_t speed_register);

// A reply: status, the byte that balances the sum, then `data`.
[[nodiscard]] Bytes reply(std::uint8_t status, std::span<const std::uint8_t> data);
// The position count of a 6-byte position reply (bytes 2-5, big-endian).
[[nodiscard]] std::optional<std::int32_t> position_count(std::span<const std::uint8_t> reply);
[[nodiscard]] Bytes position_reply(std::int32_t count);
// What the author's comments expect for INIT (er1.md §1.1): 00 A9 34 10 00 13.
[[nodiscard]] Bytes init_reply();

}  // namespace playerkit::hardware::er1
