// The codecs of a quarter of the wire structs, compiled here once
// (codec_instances.hpp).
#include "protocol/codec_instances.hpp"

namespace playerkit::protocol {

#define PLAYERKIT_DEFINE_CODECS(T) PLAYERKIT_CODEC_INSTANCES(, T)
PLAYERKIT_WIRE_STRUCTS_B(PLAYERKIT_DEFINE_CODECS)

}  // namespace playerkit::protocol
