#include "families/amtecpowercube/protocol/powercube_frames.hpp"

#include <bit>
#include <numeric>

namespace playerkit::hardware::powercube {

std::uint8_t check_byte(std::uint8_t module, std::span<const std::uint8_t> data) {
  // The reference adds the sum's high byte too, a no-op on an 8-bit sum (§1).
  return static_cast<std::uint8_t>(std::accumulate(data.begin(), data.end(), unsigned{module}));
}

std::uint8_t header_d1(std::uint8_t module) { return static_cast<std::uint8_t>(0x04 | (module >> 3)); }

std::uint8_t header_d2(std::uint8_t module, std::size_t length) {
  return static_cast<std::uint8_t>(((module & 0x07) << 5) | (length & 0x1F));
}

std::vector<std::uint8_t> encode(std::uint8_t module, std::span<const std::uint8_t> data) {
  std::vector<std::uint8_t> content{header_d1(module), header_d2(module, data.size())};
  content.insert(content.end(), data.begin(), data.end());
  content.push_back(check_byte(module, data));
  return framing::stuff(content, frame_options().stuffing);
}

std::vector<std::uint8_t> encode(Module module, std::span<const std::uint8_t> data) {
  return encode(static_cast<std::uint8_t>(module), data);
}

std::optional<Frame> decode(std::span<const std::uint8_t> telegram) {
  const auto content = framing::unstuff(telegram, frame_options().stuffing);
  if (!content || content->size() < 3) return std::nullopt;
  Frame frame;
  frame.module = static_cast<std::uint8_t>((((*content)[0] & 0x03) << 3) | ((*content)[1] >> 5));
  frame.data.assign(content->begin() + 2, content->end() - 1);
  frame.check = content->back();
  return frame;
}

bool check_holds(const Frame& frame) { return check_byte(frame.module, frame.data) == frame.check; }

framing::DleOptions frame_options() {
  framing::DleOptions options;
  options.max_length = kLongestFrame;
  options.name = "powercube";
  return options;
}

std::vector<std::uint8_t> reset_data() { return {static_cast<std::uint8_t>(CommandCode::reset)}; }
std::vector<std::uint8_t> home_data() { return {static_cast<std::uint8_t>(CommandCode::home)}; }
std::vector<std::uint8_t> halt_data() { return {static_cast<std::uint8_t>(CommandCode::halt)}; }

std::vector<std::uint8_t> get_data(Parameter parameter) {
  return {static_cast<std::uint8_t>(CommandCode::get_extended), static_cast<std::uint8_t>(parameter)};
}

std::vector<std::uint8_t> set_float_data(Parameter parameter, float value) {
  std::vector<std::uint8_t> data{static_cast<std::uint8_t>(CommandCode::set_extended),
                                 static_cast<std::uint8_t>(parameter)};
  append_u32(data, float_bits(value));
  return data;
}

std::vector<std::uint8_t> step_data(float radians, std::uint16_t milliseconds) {
  std::vector<std::uint8_t> data{static_cast<std::uint8_t>(CommandCode::set_motion),
                                 static_cast<std::uint8_t>(MotionMode::step)};
  append_u32(data, float_bits(radians));
  data.push_back(static_cast<std::uint8_t>(milliseconds & 0xFF));
  data.push_back(static_cast<std::uint8_t>(milliseconds >> 8));
  return data;
}

std::vector<std::uint8_t> velocity_data(float radians_per_second) {
  std::vector<std::uint8_t> data{static_cast<std::uint8_t>(CommandCode::set_motion),
                                 static_cast<std::uint8_t>(MotionMode::velocity)};
  append_u32(data, float_bits(radians_per_second));
  return data;
}

std::vector<std::uint8_t> value_reply_data(Parameter parameter, std::uint32_t raw) {
  auto data = get_data(parameter);
  append_u32(data, raw);
  return data;
}

std::uint32_t float_bits(float value) { return std::bit_cast<std::uint32_t>(value); }
float float_from_bits(std::uint32_t bits) { return std::bit_cast<float>(bits); }

std::uint32_t read_u32(std::span<const std::uint8_t> four) {
  return static_cast<std::uint32_t>(four[0]) | static_cast<std::uint32_t>(four[1]) << 8 |
         static_cast<std::uint32_t>(four[2]) << 16 | static_cast<std::uint32_t>(four[3]) << 24;
}

void append_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<std::uint8_t>(value >> shift));
}

std::optional<std::uint32_t> reply_value(const Frame& reply, Parameter parameter) {
  if (reply.data.size() < 6 || reply.data[0] != static_cast<std::uint8_t>(CommandCode::get_extended) ||
      reply.data[1] != static_cast<std::uint8_t>(parameter)) {
    return std::nullopt;
  }
  return read_u32(std::span(reply.data).subspan(2, 4));
}

}  // namespace playerkit::hardware::powercube
