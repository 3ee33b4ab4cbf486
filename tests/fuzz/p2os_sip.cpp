// P2OS bytes through hardware::p2os: a stream cut into frames by
// P2osFrameFormat, each valid frame's payload decoded as the driver does
// (SIP, GYROPAC, SYNC2 reply and the robot parameter row it selects,
// SERAUX/SERAUX2 and CMUcam messages) or, for the host's direction, as the
// emulator reads commands. What decodes must encode and decode to the same
// value again.
//
// Input: byte 0 picks the direction (bit 0) and seeds the chunk sizes.

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "frame_stream.hpp"
#include "families/p2os/protocol/aux_serial.hpp"
#include "families/p2os/protocol/commands.hpp"
#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/frame_format.hpp"
#include "families/p2os/protocol/gyro_packet.hpp"
#include "families/p2os/protocol/packet_types.hpp"
#include "families/p2os/protocol/robot_params.hpp"
#include "families/p2os/protocol/sip.hpp"
#include "families/p2os/protocol/sync.hpp"

namespace playerkit::fuzz {
namespace p2os_sip_detail {

namespace p2os = hardware::p2os;
constexpr const char* kTarget = "p2os_sip";

void check(bool holds, const char* what) {
  if (!holds) invariant_failed(kTarget, what);
}

void robot_packet(std::span<const std::uint8_t> payload) {
  const std::uint8_t type = payload[0];
  try {
    if (p2os::is_standard_sip(type)) {
      const auto sip = p2os::decode_sip(payload);
      check(p2os::decode_sip(p2os::encode_sip(sip)) == sip, "SIP changed through encode_sip");
      (void)p2os::compass_degrees(sip.compass);
    } else if (type == p2os::packet_type::gyro) {
      const auto gyro = p2os::decode_gyro_packet(payload);
      check(p2os::decode_gyro_packet(p2os::encode_gyro_packet(gyro)) == gyro, "GYROPAC changed through encode");
      (void)gyro.average_rate();
    } else if (type == p2os::packet_type::sync2) {
      const auto reply = p2os::decode_sync2_reply(payload);
      const auto& row = p2os::select_robot_params(reply.robot_class, reply.subclass);
      (void)row.heading_units_per_turn();
      (void)row.wheelbase();
      if (reply.name.size() <= p2os::kMaxSyncStringLength && reply.robot_class.size() <= p2os::kMaxSyncStringLength &&
          reply.subclass.size() <= p2os::kMaxSyncStringLength) {
        check(p2os::decode_sync2_reply(p2os::encode_sync2_reply(reply)) == reply, "SYNC2 reply changed");
      }
    } else if (type == p2os::packet_type::serial_aux || type == p2os::packet_type::serial_aux2) {
      const auto aux = p2os::decode_aux_serial(payload);
      check(p2os::decode_aux_serial(p2os::encode_aux_serial(aux)) == aux, "SERAUX changed through encode");
      if (const auto cmucam = p2os::find_cmucam_message(aux.data)) {
        if (const auto* blob = std::get_if<p2os::CmucamTracking>(&*cmucam)) (void)blob->area();
      }
    }
  } catch (const p2os::DecodeError&) {
  }
}

void host_packet(std::span<const std::uint8_t> payload) {
  try {
    const auto command = p2os::decode_command(payload);
    (void)p2os::command_name(command.number, true);
    (void)p2os::command_name(command.number, false);
    if (command.number == p2os::command::vel2) (void)p2os::decode_vel2(command.magnitude);
    (void)p2os::encode_command(command);
  } catch (const p2os::DecodeError&) {
  }
}

}  // namespace p2os_sip_detail

int p2os_sip(const std::uint8_t* data, std::size_t size) {
  using namespace p2os_sip_detail;
  ByteSource in(data, size);
  const std::uint8_t control = in.byte();
  const bool from_robot = (control & 1) == 0;
  const p2os::P2osFrameFormat format(from_robot ? p2os::kMaxLengthByteFromRobot : p2os::kMaxLengthByteToRobot);
  split_frames(kTarget, format, in.rest(), control, [&](std::span<const std::uint8_t> frame, bool valid) {
    if (!valid) return;
    std::span<const std::uint8_t> payload;
    try {
      payload = p2os::frame_payload(frame);
    } catch (const p2os::DecodeError&) {
      invariant_failed(kTarget, "frame_payload refuses a frame P2osFrameFormat accepted");
    }
    check(!payload.empty(), "an accepted frame without a payload");
    if (from_robot) robot_packet(payload); else host_packet(payload);
  });
  return 0;
}

}  // namespace playerkit::fuzz
