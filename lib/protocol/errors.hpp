#pragma once
// Errors raised when bytes or JSON do not fit a wire struct. Messages name the
// struct, the field, and the sizes involved, because the person reading them is
// usually looking at a hex dump or a log line.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace playerkit::protocol {

class DecodeError : public std::runtime_error {
 public:
  DecodeError(std::string_view struct_name, std::string_view field_name, std::size_t expected,
              std::size_t got, std::string message);

  // "player_laser_data_t: payload truncated in field 'intensity': expected 1213 bytes, got 900"
  static DecodeError truncated(std::string_view struct_name, std::string_view field_name,
                               std::size_t expected, std::size_t got);
  // "player_position_data_t: payload too long: expected at most 25 bytes, got 30"
  static DecodeError oversized(std::string_view struct_name, std::size_t expected,
                               std::size_t got);
  // "player_localize_data_t: field 'hypoths': 100 bytes are not a whole number of 88-byte elements"
  static DecodeError ragged(std::string_view struct_name, std::string_view field_name,
                            std::size_t element_size, std::size_t got);
  // "player_laser_data_t: field 'ranges': count 500 exceeds the 401 elements it can hold"
  static DecodeError bad_count(std::string_view struct_name, std::string_view field_name,
                               std::size_t count, std::size_t capacity);

  // "player_camera_data_t: field 'image': its count says 7 elements, the payload holds 6"
  static DecodeError count_mismatch(std::string_view struct_name, std::string_view field_name,
                                    std::size_t count, std::size_t present);

  const std::string& struct_name() const { return struct_name_; }
  const std::string& field_name() const { return field_name_; }
  std::size_t expected() const { return expected_; }
  std::size_t got() const { return got_; }

 private:
  std::string struct_name_;
  std::string field_name_;
  std::size_t expected_;
  std::size_t got_;
};

// A value that cannot be put on the wire (too many elements for its field).
class EncodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// JSON that does not describe a payload; the message starts with the field path.
class JsonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace playerkit::protocol
