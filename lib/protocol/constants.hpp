#pragma once
// Protocol-wide constants of Player 1.5 (wire-format.md §3-§4) and the `player`
// device's own codes. Per-interface constants live beside their structs in messages/.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace playerkit::protocol {

inline constexpr std::uint16_t kStx = 0x5878;  // header start marker: bytes 'X' 'x'
inline constexpr std::size_t kHeaderSize = 32;
// The default 1.5 build; clients compiled against an installed player.h assume it.
inline constexpr std::size_t kMaxMessageSize = 8192;
inline constexpr std::size_t kMaxPayloadSize = kMaxMessageSize - kHeaderSize;  // 8160
inline constexpr std::size_t kMaxRequestReplySize = 4096;  // requests/replies kept by devices
inline constexpr std::uint16_t kDefaultPort = 6665;
inline constexpr std::size_t kBannerSize = 32;  // PLAYER_IDENT_STRLEN
inline constexpr std::string_view kBannerPrefix = "Player v.";
inline constexpr std::string_view kProtocolVersion = "1.5";
inline constexpr std::size_t kKeyLength = 32;  // PLAYER_KEYLEN
inline constexpr std::size_t kMaxDeviceStringLength = 64;
inline constexpr std::size_t kMaxDevices = 64;  // capacity of the device-list reply

enum class MessageType : std::uint16_t {
  kData = 1,     // sensor data, server to client
  kCommand = 2,  // actuator command, client to server, never answered
  kRequest = 3,  // configuration request
  kAck = 4,      // positive reply
  kSynch = 5,    // end of a data round, zero length
  kNack = 6,     // request understood but refused or failed
  kError = 7,    // no permission, unknown device, full queue
};

// "data", "cmd", "req", "ack", "synch", "nack", "err"
std::string_view to_string(MessageType type);
std::optional<MessageType> parse_message_type(std::string_view name);
bool is_reply(MessageType type);

// Access letters of the DEV request (player_device_req_t.access).
enum class Access : std::uint8_t {
  kRead = 'r',
  kWrite = 'w',
  kAll = 'a',    // read and write
  kClose = 'c',
  kError = 'e',  // only ever returned: the device could not be opened
};

enum class DataMode : std::uint8_t {
  kPushAll = 0,  // every subscribed device at the set rate, fresh or not
  kPullAll = 1,  // everything, only after a data request
  kPushNew = 2,  // at the set rate, only data with a new timestamp (default)
  kPullNew = 3,  // only new data, only after a data request
};

// "push-all", "pull-all", "push-new", "pull-new"
std::string_view to_string(DataMode mode);
std::optional<DataMode> parse_data_mode(std::string_view name);

// Request subtypes of the `player` device (uint16 on the wire, unlike other devices).
inline constexpr std::uint16_t kPlayerDevlistReq = 1;
inline constexpr std::uint16_t kPlayerDriverinfoReq = 2;
inline constexpr std::uint16_t kPlayerDevReq = 3;
inline constexpr std::uint16_t kPlayerDataReq = 4;
inline constexpr std::uint16_t kPlayerDatamodeReq = 5;
inline constexpr std::uint16_t kPlayerDatafreqReq = 6;
inline constexpr std::uint16_t kPlayerAuthReq = 7;
inline constexpr std::uint16_t kPlayerNameserviceReq = 8;

}  // namespace playerkit::protocol
