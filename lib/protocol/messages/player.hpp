#pragma once
// Player 1.5 `player` payloads: constants and packed structs, field for field
// as in wire-format.md §5 (names, order, sizes). Values are in wire units.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <vector>

#include "protocol/fields.hpp"
#include "protocol/fixed_string.hpp"

namespace playerkit::protocol {

struct DeviceId {
  static constexpr std::string_view kWireName = "player_device_id_t";
  static constexpr std::size_t kWireSize = 6;

  std::uint16_t code = 0;  // interface code
  std::uint16_t index = 0;  // device index
  std::uint16_t port = 0;  // TCP port the device is served on

  static constexpr auto fields() {
    return std::tuple{field("code", &DeviceId::code),
                      field("index", &DeviceId::index),
                      field("port", &DeviceId::port)};
  }
  friend bool operator==(const DeviceId&, const DeviceId&) = default;
};

struct DeviceList {
  static constexpr std::string_view kWireName = "player_device_devlist_t";
  static constexpr std::size_t kWireSize = 388;

  std::uint16_t subtype = 0;  // PLAYER_PLAYER_DEVLIST_REQ (1)
  std::uint16_t device_count = 0;  // number of valid entries in devices[]
  std::array<DeviceId, 64> devices{};  // device ids (6 bytes each); unused entries are zero

  static constexpr auto fields() {
    return std::tuple{field("subtype", &DeviceList::subtype),
                      field("device_count", &DeviceList::device_count),
                      counted("devices", &DeviceList::devices, &DeviceList::device_count)};
  }
  friend bool operator==(const DeviceList&, const DeviceList&) = default;
};

struct DriverInfo {
  static constexpr std::string_view kWireName = "player_device_driverinfo_t";
  static constexpr std::size_t kWireSize = 72;

  std::uint16_t subtype = 0;  // PLAYER_PLAYER_DRIVERINFO_REQ (2)
  DeviceId id{};  // device asked about (code, index, port)
  FixedString<64> driver_name{};  // NUL-terminated driver name, filled by server

  static constexpr auto fields() {
    return std::tuple{field("subtype", &DriverInfo::subtype),
                      field("id", &DriverInfo::id),
                      field("driver_name", &DriverInfo::driver_name)};
  }
  friend bool operator==(const DriverInfo&, const DriverInfo&) = default;
};

struct DeviceAccessRequest {
  static constexpr std::string_view kWireName = "player_device_req_t";
  static constexpr std::size_t kWireSize = 7;

  std::uint16_t subtype = 0;  // PLAYER_PLAYER_DEV_REQ (3)
  std::uint16_t code = 0;  // interface code wanted
  std::uint16_t index = 0;  // device index wanted
  std::uint8_t access = 0;  // requested access: 'r','w','a' or 'c' (ASCII)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &DeviceAccessRequest::subtype),
                      field("code", &DeviceAccessRequest::code),
                      field("index", &DeviceAccessRequest::index),
                      field("access", &DeviceAccessRequest::access)};
  }
  friend bool operator==(const DeviceAccessRequest&, const DeviceAccessRequest&) = default;
};

struct DeviceAccessReply {
  static constexpr std::string_view kWireName = "player_device_resp_t";
  static constexpr std::size_t kWireSize = 71;

  std::uint16_t subtype = 0;  // echo of request subtype
  std::uint16_t code = 0;  // echo of requested code
  std::uint16_t index = 0;  // echo of requested index
  std::uint8_t access = 0;  // access actually granted ('r','w','a','c' or 'e')
  FixedString<64> driver_name{};  // NUL-padded driver name (empty if none)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &DeviceAccessReply::subtype),
                      field("code", &DeviceAccessReply::code),
                      field("index", &DeviceAccessReply::index),
                      field("access", &DeviceAccessReply::access),
                      field("driver_name", &DeviceAccessReply::driver_name)};
  }
  friend bool operator==(const DeviceAccessReply&, const DeviceAccessReply&) = default;
};

struct DataRequest {
  static constexpr std::string_view kWireName = "player_device_data_req_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint16_t subtype = 0;  // PLAYER_PLAYER_DATA_REQ (4)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &DataRequest::subtype)};
  }
  friend bool operator==(const DataRequest&, const DataRequest&) = default;
};

struct DataModeRequest {
  static constexpr std::string_view kWireName = "player_device_datamode_req_t";
  static constexpr std::size_t kWireSize = 3;

  std::uint16_t subtype = 0;  // PLAYER_PLAYER_DATAMODE_REQ (5)
  std::uint8_t mode = 0;  // one of PLAYER_DATAMODE_* (0..3)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &DataModeRequest::subtype),
                      field("mode", &DataModeRequest::mode)};
  }
  friend bool operator==(const DataModeRequest&, const DataModeRequest&) = default;
};

struct DataFrequencyRequest {
  static constexpr std::string_view kWireName = "player_device_datafreq_req_t";
  static constexpr std::size_t kWireSize = 4;

  std::uint16_t subtype = 0;  // PLAYER_PLAYER_DATAFREQ_REQ (6)
  std::uint16_t frequency = 0;  // push rate in Hz

  static constexpr auto fields() {
    return std::tuple{field("subtype", &DataFrequencyRequest::subtype),
                      field("frequency", &DataFrequencyRequest::frequency)};
  }
  friend bool operator==(const DataFrequencyRequest&, const DataFrequencyRequest&) = default;
};

struct AuthRequest {
  static constexpr std::string_view kWireName = "player_device_auth_req_t";
  static constexpr std::size_t kWireSize = 34;

  std::uint16_t subtype = 0;  // PLAYER_PLAYER_AUTH_REQ (7)
  FixedString<32> auth_key{};  // key text, NUL-terminated (last byte forced to NUL)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &AuthRequest::subtype),
                      field("auth_key", &AuthRequest::auth_key)};
  }
  friend bool operator==(const AuthRequest&, const AuthRequest&) = default;
};

struct NameServiceRequest {
  static constexpr std::string_view kWireName = "player_device_nameservice_req_t";
  static constexpr std::size_t kWireSize = 68;

  std::uint16_t subtype = 0;  // PLAYER_PLAYER_NAMESERVICE_REQ (8)
  FixedString<64> name{};  // robot name to look up
  std::uint16_t port = 0;  // reply: port of that robot, 0 if unknown

  static constexpr auto fields() {
    return std::tuple{field("subtype", &NameServiceRequest::subtype),
                      field("name", &NameServiceRequest::name),
                      field("port", &NameServiceRequest::port)};
  }
  friend bool operator==(const NameServiceRequest&, const NameServiceRequest&) = default;
};

}  // namespace playerkit::protocol
