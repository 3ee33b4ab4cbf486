#include "protocol/errors.hpp"

namespace playerkit::protocol {

DecodeError::DecodeError(std::string_view struct_name, std::string_view field_name,
                         std::size_t expected, std::size_t got, std::string message)
    : std::runtime_error(std::move(message)),
      struct_name_(struct_name),
      field_name_(field_name),
      expected_(expected),
      got_(got) {}

DecodeError DecodeError::truncated(std::string_view struct_name, std::string_view field_name,
                                   std::size_t expected, std::size_t got) {
  return {struct_name, field_name, expected, got,
          std::string(struct_name) + ": payload truncated in field '" + std::string(field_name) +
              "': expected " + std::to_string(expected) + " bytes, got " + std::to_string(got)};
}

DecodeError DecodeError::oversized(std::string_view struct_name, std::size_t expected,
                                   std::size_t got) {
  return {struct_name, "", expected, got,
          std::string(struct_name) + ": payload too long: expected at most " +
              std::to_string(expected) + " bytes, got " + std::to_string(got)};
}

DecodeError DecodeError::ragged(std::string_view struct_name, std::string_view field_name,
                                std::size_t element_size, std::size_t got) {
  return {struct_name, field_name, element_size, got,
          std::string(struct_name) + ": field '" + std::string(field_name) + "': " +
              std::to_string(got) + " bytes are not a whole number of " +
              std::to_string(element_size) + "-byte elements"};
}

DecodeError DecodeError::bad_count(std::string_view struct_name, std::string_view field_name,
                                   std::size_t count, std::size_t capacity) {
  return {struct_name, field_name, capacity, count,
          std::string(struct_name) + ": field '" + std::string(field_name) + "': count " +
              std::to_string(count) + " exceeds the " + std::to_string(capacity) +
              " elements it can hold"};
}

DecodeError DecodeError::count_mismatch(std::string_view struct_name, std::string_view field_name,
                                        std::size_t count, std::size_t present) {
  return {struct_name, field_name, count, present,
          std::string(struct_name) + ": field '" + std::string(field_name) + "': its count says " +
              std::to_string(count) + " elements, the payload holds " + std::to_string(present)};
}

}  // namespace playerkit::protocol
