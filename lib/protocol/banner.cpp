#include "protocol/banner.hpp"

#include <algorithm>
#include <stdexcept>

namespace playerkit::protocol {

Banner make_banner(std::string_view version) {
  Banner banner{};
  if (kBannerPrefix.size() + version.size() >= kBannerSize) {
    throw std::length_error("banner version text too long: " + std::string(version));
  }
  auto out = std::copy(kBannerPrefix.begin(), kBannerPrefix.end(), banner.begin());
  std::copy(version.begin(), version.end(), out);
  return banner;
}

std::optional<std::string> parse_banner(std::span<const std::uint8_t> bytes) {
  if (bytes.size() != kBannerSize) return std::nullopt;
  const auto nul = std::find(bytes.begin(), bytes.end(), 0);
  const std::string text(bytes.begin(), nul);
  if (!text.starts_with(kBannerPrefix)) return std::nullopt;
  // Everything after the text must be padding.
  if (std::any_of(nul, bytes.end(), [](std::uint8_t b) { return b != 0; })) return std::nullopt;
  return text.substr(kBannerPrefix.size());
}

}  // namespace playerkit::protocol
