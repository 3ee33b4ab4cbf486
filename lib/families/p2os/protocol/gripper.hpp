#pragma once
// Gripper command arguments, state bits (SIP TIMER high byte) and beam bits
// (SIP DIGIN), p2os.md §3.3.

#include <cstdint>

namespace playerkit::hardware::p2os {

namespace gripper_command {
inline constexpr std::uint8_t open = 1;
inline constexpr std::uint8_t close = 2;
inline constexpr std::uint8_t stop = 3;
inline constexpr std::uint8_t lift_up = 4;
inline constexpr std::uint8_t lift_down = 5;
inline constexpr std::uint8_t lift_stop = 6;
inline constexpr std::uint8_t store = 7;     // close and lift
inline constexpr std::uint8_t deploy = 8;    // open and lower
inline constexpr std::uint8_t halt = 15;     // stop paddles and lift
inline constexpr std::uint8_t press = 16;    // close with the pressure sent by GRIPPERVAL
inline constexpr std::uint8_t lift_carry = 17;  // lift by the amount sent by GRIPPERVAL
}  // namespace gripper_command

namespace gripper_state {
inline constexpr std::uint8_t paddles_open = 0x01;
inline constexpr std::uint8_t paddles_closed = 0x02;
inline constexpr std::uint8_t paddles_moving = 0x04;
inline constexpr std::uint8_t paddles_error = 0x08;
inline constexpr std::uint8_t lift_up = 0x10;
inline constexpr std::uint8_t lift_down = 0x20;
inline constexpr std::uint8_t lift_moving = 0x40;
inline constexpr std::uint8_t lift_error = 0x80;
}  // namespace gripper_state

namespace gripper_beam {
inline constexpr std::uint8_t gripper_limit = 0x01;
inline constexpr std::uint8_t lift_limit = 0x02;
inline constexpr std::uint8_t outer_beam = 0x04;
inline constexpr std::uint8_t inner_beam = 0x08;
inline constexpr std::uint8_t left_paddle_open = 0x10;
inline constexpr std::uint8_t right_paddle_open = 0x20;
}  // namespace gripper_beam

}  // namespace playerkit::hardware::p2os
