#include "families/sick/protocol/config_block.hpp"

namespace playerkit::hardware::sick {

std::uint16_t ConfigBlock::blanking() const {
  return static_cast<std::uint16_t>(at_body_offset(kBlankingOffset) |
                                    (at_body_offset(kBlankingOffset + 1) << 8));
}

}  // namespace playerkit::hardware::sick
