#pragma once
// Player 1.5 `fiducial` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kFiducialMaxSamples = 32;  // capacity of fiducial list
inline constexpr std::size_t kFiducialMaxMsgLen = 32;  // capacity of fiducial message body
inline constexpr std::uint8_t kFiducialGetGeom = 1;  // get detector geometry
inline constexpr std::uint8_t kFiducialGetFov = 2;  // get field of view
inline constexpr std::uint8_t kFiducialSetFov = 3;  // set field of view
inline constexpr std::uint8_t kFiducialSendMsg = 4;  // send a message
inline constexpr std::uint8_t kFiducialRecvMsg = 5;  // read last received message
inline constexpr std::uint8_t kFiducialExchangeMsg = 6;  // send then read

struct FiducialItem {
  static constexpr std::string_view kWireName = "player_fiducial_item_t";
  static constexpr std::size_t kWireSize = 14;

  std::int16_t id = 0;  // fiducial id, -1 if unidentified
  std::array<std::int16_t, 3> pose{};  // range mm, bearing deg, orientation deg
  std::array<std::int16_t, 3> upose{};  // uncertainty of the same three

  static constexpr auto fields() {
    return std::tuple{field("id", &FiducialItem::id),
                      field("pose", &FiducialItem::pose),
                      field("upose", &FiducialItem::upose)};
  }
  friend bool operator==(const FiducialItem&, const FiducialItem&) = default;
};

struct FiducialData {
  static constexpr std::string_view kWireName = "player_fiducial_data_t";
  static constexpr std::size_t kWireSize = 450;

  std::uint16_t count = 0;  // number of valid entries
  std::array<FiducialItem, 32> fiducials{};  // detections (14 bytes each)

  static constexpr auto fields() {
    return std::tuple{field("count", &FiducialData::count),
                      counted("fiducials", &FiducialData::fiducials, &FiducialData::count)};
  }
  friend bool operator==(const FiducialData&, const FiducialData&) = default;
};

// Geometry/angles are declared uint16 in player.h; read as int16 like laser geometry, so mounts behind or right of the centre work; same bits.
struct FiducialGeom {
  static constexpr std::string_view kWireName = "player_fiducial_geom_t";
  static constexpr std::size_t kWireSize = 15;

  std::uint8_t subtype = 0;  // PLAYER_FIDUCIAL_GET_GEOM (1)
  std::array<std::int16_t, 3> pose{};  // detector pose in robot frame: x mm, y mm, yaw deg
  std::array<std::uint16_t, 2> size{};  // detector size: mm, mm
  std::array<std::uint16_t, 2> fiducial_size{};  // marker size: mm, mm

  static constexpr auto fields() {
    return std::tuple{field("subtype", &FiducialGeom::subtype),
                      field("pose", &FiducialGeom::pose),
                      field("size", &FiducialGeom::size),
                      field("fiducial_size", &FiducialGeom::fiducial_size)};
  }
  friend bool operator==(const FiducialGeom&, const FiducialGeom&) = default;
};

struct FiducialFov {
  static constexpr std::string_view kWireName = "player_fiducial_fov_t";
  static constexpr std::size_t kWireSize = 7;

  std::uint8_t subtype = 0;  // PLAYER_FIDUCIAL_GET_FOV (2) or _SET_FOV (3)
  std::uint16_t min_range = 0;  // minimum range, mm
  std::uint16_t max_range = 0;  // maximum range, mm
  std::uint16_t view_angle = 0;  // field of view, degrees

  static constexpr auto fields() {
    return std::tuple{field("subtype", &FiducialFov::subtype),
                      field("min_range", &FiducialFov::min_range),
                      field("max_range", &FiducialFov::max_range),
                      field("view_angle", &FiducialFov::view_angle)};
  }
  friend bool operator==(const FiducialFov&, const FiducialFov&) = default;
};

struct FiducialMsg {
  static constexpr std::string_view kWireName = "player_fiducial_msg_t";
  static constexpr std::size_t kWireSize = 38;

  std::int32_t target_id = 0;  // fiducial id of addressee (-1 = broadcast)
  std::array<std::uint8_t, 32> bytes{};  // message bytes
  std::uint8_t len = 0;  // number of valid bytes
  std::uint8_t intensity = 0;  // transmit power / received intensity, 0-255

  static constexpr auto fields() {
    return std::tuple{field("target_id", &FiducialMsg::target_id),
                      counted("bytes", &FiducialMsg::bytes, &FiducialMsg::len),
                      field("len", &FiducialMsg::len),
                      field("intensity", &FiducialMsg::intensity)};
  }
  friend bool operator==(const FiducialMsg&, const FiducialMsg&) = default;
};

struct FiducialMsgRxRequest {
  static constexpr std::string_view kWireName = "player_fiducial_msg_rx_req_t";
  static constexpr std::size_t kWireSize = 2;

  std::uint8_t subtype = 0;  // PLAYER_FIDUCIAL_RECV_MSG (5)
  std::uint8_t consume = 0;  // non-zero: remove message from buffer after reading

  static constexpr auto fields() {
    return std::tuple{field("subtype", &FiducialMsgRxRequest::subtype),
                      field("consume", &FiducialMsgRxRequest::consume)};
  }
  friend bool operator==(const FiducialMsgRxRequest&, const FiducialMsgRxRequest&) = default;
};

struct FiducialMsgTxRequest {
  static constexpr std::string_view kWireName = "player_fiducial_msg_tx_req_t";
  static constexpr std::size_t kWireSize = 40;

  std::uint8_t subtype = 0;  // PLAYER_FIDUCIAL_SEND_MSG (4)
  std::uint8_t consume = 0;  // non-zero: send once only
  FiducialMsg msg{};  // message to send (38 bytes)

  static constexpr auto fields() {
    return std::tuple{field("subtype", &FiducialMsgTxRequest::subtype),
                      field("consume", &FiducialMsgTxRequest::consume),
                      field("msg", &FiducialMsgTxRequest::msg)};
  }
  friend bool operator==(const FiducialMsgTxRequest&, const FiducialMsgTxRequest&) = default;
};

struct FiducialMsgTxRxRequest {
  static constexpr std::string_view kWireName = "player_fiducial_msg_txrx_req_t";
  static constexpr std::size_t kWireSize = 41;

  std::uint8_t subtype = 0;  // PLAYER_FIDUCIAL_EXCHANGE_MSG (6)
  FiducialMsg msg{};  // message to send (38 bytes)
  std::uint8_t consume_send = 0;  // send once only
  std::uint8_t consume_reply = 0;  // remove reply from buffer

  static constexpr auto fields() {
    return std::tuple{field("subtype", &FiducialMsgTxRxRequest::subtype),
                      field("msg", &FiducialMsgTxRxRequest::msg),
                      field("consume_send", &FiducialMsgTxRxRequest::consume_send),
                      field("consume_reply", &FiducialMsgTxRxRequest::consume_reply)};
  }
  friend bool operator==(const FiducialMsgTxRxRequest&, const FiducialMsgTxRxRequest&) = default;
};

}  // namespace playerkit::protocol
