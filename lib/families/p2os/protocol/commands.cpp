#include "families/p2os/protocol/commands.hpp"

#include "families/p2os/protocol/byte_cursor.hpp"
#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"

#include <cstdlib>

namespace playerkit::hardware::p2os {

Command Command::plain(std::uint8_t number) {
  Command command;
  command.number = number;
  return command;
}

Command Command::with_integer(std::uint8_t number, int value) {
  const int magnitude = std::abs(value);
  if (magnitude > 0xFFFF) {
    throw EncodeError("P2OS " + command_name(number, true) + ": argument " +
                      std::to_string(value) + " does not fit in 16 bits");
  }
  Command command = plain(number);
  command.form = ArgumentForm::integer;
  command.magnitude = static_cast<std::uint16_t>(magnitude);
  command.negative = value < 0;
  return command;
}

Command Command::type_only(std::uint8_t number) {
  Command command = plain(number);
  command.form = ArgumentForm::type_only;
  return command;
}

Command Command::with_string(std::uint8_t number, std::string text) {
  Command command = plain(number);
  command.form = ArgumentForm::string;
  command.text = std::move(text);
  return command;
}

std::vector<std::uint8_t> encode_command(const Command& command) {
  // Sized once: besides saving reallocations, this keeps GCC 12 at -O3 from
  // reporting the growth-then-copy below as out of bounds (a false positive).
  std::vector<std::uint8_t> payload;
  payload.reserve(4 + command.text.size());
  payload.push_back(command.number);
  switch (command.form) {
    case ArgumentForm::none:
      break;
    case ArgumentForm::integer:
      payload.push_back(command.negative ? argument_type::negative_integer : argument_type::integer);
      detail::append_u16(payload, command.magnitude);
      break;
    case ArgumentForm::type_only:
      payload.push_back(argument_type::integer);
      break;
    case ArgumentForm::string:
      if (command.text.size() > 0xFF) {
        throw EncodeError("P2OS " + command_name(command.number, true) + ": string of " +
                          std::to_string(command.text.size()) +
                          " characters is longer than its length byte allows (255)");
      }
      payload.push_back(argument_type::string);
      payload.push_back(static_cast<std::uint8_t>(command.text.size()));
      payload.insert(payload.end(), command.text.begin(), command.text.end());
      break;
  }
  if (payload.size() + kChecksumSize > kMaxLengthByteToRobot) {
    throw EncodeError("P2OS " + command_name(command.number, true) + ": " +
                      std::to_string(payload.size()) +
                      " payload bytes exceed what a robot accepts (N <= 200)");
  }
  return payload;
}

std::vector<std::uint8_t> command_frame(const Command& command) {
  return build_frame(encode_command(command));
}

Command decode_command(std::span<const std::uint8_t> payload) {
  detail::ByteCursor cursor(payload, "P2OS command");
  Command command = Command::plain(cursor.u8("command number"));
  if (cursor.remaining() == 0) return command;
  const std::uint8_t type = cursor.u8("argument type");
  switch (type) {
    case argument_type::integer:
    case argument_type::negative_integer:
      if (cursor.remaining() == 0) {
        command.form = ArgumentForm::type_only;
        command.negative = type == argument_type::negative_integer;
        return command;
      }
      command.form = ArgumentForm::integer;
      command.negative = type == argument_type::negative_integer;
      command.magnitude = cursor.u16("integer argument");
      return command;
    case argument_type::string: {
      command.form = ArgumentForm::string;
      const std::uint8_t length = cursor.u8("string length");
      const auto text = cursor.take(length, "string argument");
      command.text.assign(text.begin(), text.end());
      return command;
    }
    default:
      throw DecodeError("P2OS command " + std::to_string(command.number) + ": argument type " +
                        detail::hex_byte(type) + " is none of ARGINT 0x3B, ARGNINT 0x1B, ARGSTR 0x2B");
  }
}

std::uint16_t encode_vel2(Vel2Wheels wheels) {
  return static_cast<std::uint16_t>((static_cast<std::uint8_t>(wheels.left) << 8) |
                                    static_cast<std::uint8_t>(wheels.right));
}

Vel2Wheels decode_vel2(std::uint16_t magnitude) {
  return {.left = static_cast<std::int8_t>(static_cast<std::uint8_t>(magnitude >> 8)),
          .right = static_cast<std::int8_t>(static_cast<std::uint8_t>(magnitude & 0xFF))};
}

std::string command_name(std::uint8_t number, bool connected) {
  switch (number) {
    case command::sync0: return connected ? "PULSE" : "SYNC0";
    case command::sync1: return connected ? "OPEN" : "SYNC1";
    case command::sync2: return connected ? "CLOSE" : "SYNC2";
    case command::enable: return "ENABLE";
    case command::setv: return "SETV";
    case command::seto: return "SETO";
    case command::vel: return "VEL";
    case command::config: return "CONFIG";
    case command::rvel: return "RVEL";
    case command::sonar: return "SONAR";
    case command::stop: return "STOP";
    case command::vel2: return "VEL2";
    case command::gripper: return "GRIPPER";
    case command::gripper_value: return "GRIPPERVAL";
    case command::gripper_request: return "GRIPREQUEST";
    case command::io_request: return "IOREQUEST";
    case command::tty2: return "TTY2";
    case command::getaux: return "GETAUX";
    case command::joydrive: return "JOYDRIVE";
    case command::gyro: return "GYRO";
    case command::tty3: return "TTY3";
    case command::getaux2: return "GETAUX2";
    case command::sound: return "SOUND";
    case command::playlist: return "PLAYLIST";
    default: return "command " + std::to_string(number);
  }
}

}  // namespace playerkit::hardware::p2os
