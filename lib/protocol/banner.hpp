#pragma once
// The 32-byte ident string the server sends first: "Player v.1.5", NUL-padded.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "protocol/constants.hpp"

namespace playerkit::protocol {

using Banner = std::array<std::uint8_t, kBannerSize>;

// "Player v.<version>" followed by NULs; throws std::length_error if it does not fit.
Banner make_banner(std::string_view version = kProtocolVersion);

// The version text after "Player v." ("1.5", or "1.5 (stage)"); nullopt if the 32
// bytes are not a Player banner.
std::optional<std::string> parse_banner(std::span<const std::uint8_t> bytes);

}  // namespace playerkit::protocol
