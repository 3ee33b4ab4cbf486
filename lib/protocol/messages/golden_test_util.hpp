#pragma once
// Shared helpers for the golden-byte tests in lib/protocol/messages/*_test.cpp.
//
// Golden vectors are written by hand from the offset tables of wire-format.md §5
// and never produced by the library's encoder:
//
//   const Bytes golden = WireBytes(25)           // player_position_data_t, 25 bytes
//                            .at(0, {0x01, 0x02, 0x03, 0x04})  // xpos @0 int32
//                            ...
//                            .done();            // throws unless every byte was written
//
// WireBytes refuses to write a byte twice or outside the buffer, and done() refuses a
// vector with a byte nobody wrote, so every field of the spec table must appear exactly
// once (fields that are zero are written with zeros()).
//
// Values: every byte of a value differs (0x0102 0x11121314 ...) so that a swapped
// byte order or a field at the wrong offset shows. Negative values are written as
// ~N (== -(N + 1)) so that their wire bytes are the bitwise complement of N's:
// ~0x0102 == -0x0103 is FE FD, ~0x11121314 is EE ED EC EB.

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <set>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "protocol/binary_codec.hpp"
#include "protocol/codec_instances.hpp"
#include "protocol/errors.hpp"
#include "protocol/fields.hpp"
#include "protocol/json_codec.hpp"

namespace playerkit::protocol::golden {

using Bytes = std::vector<std::uint8_t>;

// A zeroed buffer of the spec's struct size, filled field by field at spec offsets.
// Big-endian placement is done here with shifts, independently of byte_order.hpp.
class WireBytes {
 public:
  explicit WireBytes(std::size_t size) : bytes_(size, 0), written_(size, false) {}

  // Literal bytes, in wire order, starting at a spec offset.
  WireBytes& at(std::size_t offset, std::initializer_list<std::uint8_t> bytes) {
    std::size_t i = offset;
    for (std::uint8_t b : bytes) put(i++, b);
    return *this;
  }
  WireBytes& u8(std::size_t offset, std::uint8_t v) { return at(offset, {v}); }
  WireBytes& be16(std::size_t offset, std::uint16_t v) {
    return at(offset, {static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v & 0xFF)});
  }
  WireBytes& be32(std::size_t offset, std::uint32_t v) {
    return at(offset, {static_cast<std::uint8_t>(v >> 24), static_cast<std::uint8_t>((v >> 16) & 0xFF),
                       static_cast<std::uint8_t>((v >> 8) & 0xFF), static_cast<std::uint8_t>(v & 0xFF)});
  }
  WireBytes& be64(std::size_t offset, std::uint64_t v) {
    for (std::size_t i = 0; i < 8; ++i) put(offset + i, static_cast<std::uint8_t>((v >> (56 - 8 * i)) & 0xFF));
    return *this;
  }
  // `count` zero bytes: fields (or unused array tails) whose value is zero.
  WireBytes& zeros(std::size_t offset, std::size_t count) {
    for (std::size_t i = 0; i < count; ++i) put(offset + i, 0);
    return *this;
  }
  // A NUL-padded text field of `field_size` bytes.
  WireBytes& text(std::size_t offset, std::string_view s, std::size_t field_size) {
    if (s.size() > field_size) throw std::logic_error("golden vector: text longer than its field");
    for (std::size_t i = 0; i < field_size; ++i) {
      put(offset + i, i < s.size() ? static_cast<std::uint8_t>(s[i]) : 0);
    }
    return *this;
  }

  // The finished vector; every byte must have been written exactly once.
  [[nodiscard]] Bytes done() const {
    for (std::size_t i = 0; i < written_.size(); ++i) {
      if (!written_[i]) {
        throw std::logic_error("golden vector: byte " + std::to_string(i) + " of " +
                               std::to_string(bytes_.size()) + " was never written");
      }
    }
    return bytes_;
  }

 private:
  void put(std::size_t i, std::uint8_t b) {
    if (i >= bytes_.size()) {
      throw std::logic_error("golden vector: byte " + std::to_string(i) + " is outside the " +
                             std::to_string(bytes_.size()) + "-byte struct");
    }
    if (written_[i]) throw std::logic_error("golden vector: byte " + std::to_string(i) + " written twice");
    written_[i] = true;
    bytes_[i] = b;
  }

  Bytes bytes_;
  std::vector<bool> written_;
};

inline std::string hex_window(std::span<const std::uint8_t> bytes, std::size_t center) {
  std::ostringstream out;
  const std::size_t from = center > 4 ? center - 4 : 0;
  const std::size_t to = std::min(bytes.size(), center + 5);
  out << "[@" << from << ":";
  for (std::size_t i = from; i < to; ++i) {
    static constexpr char kDigits[] = "0123456789ABCDEF";
    out << ' ' << (i == center ? "<" : "") << kDigits[bytes[i] >> 4] << kDigits[bytes[i] & 0xF]
        << (i == center ? ">" : "");
  }
  out << "]";
  return out.str();
}

// Byte-for-byte comparison that names the first differing offset.
inline ::testing::AssertionResult SameBytes(std::span<const std::uint8_t> got,
                                            std::span<const std::uint8_t> want) {
  const std::size_t common = std::min(got.size(), want.size());
  for (std::size_t i = 0; i < common; ++i) {
    if (got[i] != want[i]) {
      return ::testing::AssertionFailure() << "first difference at byte " << i << ": got "
                                           << hex_window(got, i) << ", want " << hex_window(want, i);
    }
  }
  if (got.size() != want.size()) {
    return ::testing::AssertionFailure() << "got " << got.size() << " bytes, want " << want.size();
  }
  return ::testing::AssertionSuccess();
}

// encode(value) is exactly the golden vector, and encoded_size agrees.
template <WireStruct T>
::testing::AssertionResult EncodesTo(const T& value, const Bytes& golden) {
  Bytes got;
  try {
    got = encode(value);
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << T::kWireName << ": encode threw: " << e.what();
  }
  if (encoded_size(value) != golden.size()) {
    return ::testing::AssertionFailure() << T::kWireName << ": encoded_size " << encoded_size(value)
                                         << ", golden vector has " << golden.size() << " bytes";
  }
  auto result = SameBytes(got, golden);
  if (!result) result << " (encoding " << T::kWireName << ")";
  return result;
}

// decode<T>(golden) gives back exactly `want`.
template <WireStruct T>
::testing::AssertionResult DecodesTo(const Bytes& golden, const T& want) {
  T got{};
  try {
    got = decode<T>(golden);
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << T::kWireName << ": decode of " << golden.size()
                                         << " bytes threw: " << e.what();
  }
  if (!(got == want)) {
    return ::testing::AssertionFailure() << T::kWireName << ": decoded value differs\n  got:  "
                                         << to_json(got).dump() << "\n  want: " << to_json(want).dump();
  }
  return ::testing::AssertionSuccess();
}

// from_json(to_json(value)) == value.
template <WireStruct T>
::testing::AssertionResult SurvivesJson(const T& value) {
  nlohmann::json j;
  try {
    j = to_json(value);
    const T back = from_json<T>(j);
    if (!(back == value)) {
      return ::testing::AssertionFailure() << T::kWireName << ": JSON round trip changed the value\n  json: "
                                           << j.dump() << "\n  back: " << to_json(back).dump();
    }
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << T::kWireName << ": JSON round trip threw: " << e.what()
                                         << "\n  json: " << j.dump();
  }
  return ::testing::AssertionSuccess();
}

// All three at once: encode(value) == golden, decode(golden) == value, and value
// survives JSON.
template <WireStruct T>
::testing::AssertionResult MatchesGolden(const T& value, const Bytes& golden) {
  if (auto r = EncodesTo(value, golden); !r) return r;
  if (auto r = DecodesTo(golden, value); !r) return r;
  return SurvivesJson(value);
}

// The top-level JSON keys are exactly the spec's field names.
inline ::testing::AssertionResult HasFields(const nlohmann::json& j,
                                            std::initializer_list<std::string_view> names) {
  std::set<std::string> want;
  for (auto n : names) want.emplace(n);
  std::set<std::string> got;
  for (const auto& item : j.items()) got.insert(item.key());
  if (got != want) return ::testing::AssertionFailure() << "JSON keys differ from the spec: " << j.dump();
  return ::testing::AssertionSuccess();
}

// decode<T>(bytes) throws DecodeError naming T's struct and `field`, with the
// given expected()/got() sizes (for a count error: capacity and count).
template <WireStruct T>
::testing::AssertionResult Rejects(std::span<const std::uint8_t> bytes, std::string_view field,
                                   std::size_t expected, std::size_t got) {
  try {
    (void)decode<T>(bytes);
  } catch (const DecodeError& e) {
    const std::string what = e.what();
    auto failure = [&] {
      return ::testing::AssertionFailure() << "decode<" << T::kWireName << "> of " << bytes.size()
                                           << " bytes threw \"" << what << "\" (struct '" << e.struct_name()
                                           << "', field '" << e.field_name() << "', expected " << e.expected()
                                           << ", got " << e.got() << "); wanted field '" << field
                                           << "', expected " << expected << ", got " << got;
    };
    if (e.struct_name() != T::kWireName || e.field_name() != field || e.expected() != expected ||
        e.got() != got) {
      return failure();
    }
    if (what.find(T::kWireName) == std::string::npos) return failure() << " (message lacks the struct name)";
    if (!field.empty() && what.find("'" + std::string(field) + "'") == std::string::npos) {
      return failure() << " (message lacks the field name)";
    }
    return ::testing::AssertionSuccess();
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "decode<" << T::kWireName << "> threw a non-DecodeError: " << e.what();
  }
  return ::testing::AssertionFailure() << "decode<" << T::kWireName << "> accepted " << bytes.size() << " bytes";
}

// decode<T>(bytes) succeeds.
template <WireStruct T>
::testing::AssertionResult Accepts(std::span<const std::uint8_t> bytes) {
  try {
    (void)decode<T>(bytes);
  } catch (const std::exception& e) {
    return ::testing::AssertionFailure() << "decode<" << T::kWireName << "> of " << bytes.size()
                                         << " bytes threw: " << e.what();
  }
  return ::testing::AssertionSuccess();
}

// The golden vector without its last byte, and with one extra byte.
inline Bytes drop_last(Bytes b) {
  b.pop_back();
  return b;
}
inline Bytes with_extra_byte(Bytes b) {
  b.push_back(0x5A);
  return b;
}
inline const Bytes kEmpty{};

}  // namespace playerkit::protocol::golden
