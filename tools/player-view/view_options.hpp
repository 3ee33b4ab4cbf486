#pragma once
// What player-view was asked to do, checked: the command line as CLI11 fills
// it (CommandLine) becomes ViewOptions, or a UsageError naming the flag at
// fault. Pure, so the rules are unit-tested.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "client/endpoint.hpp"
#include "exit_status.hpp"
#include "map/map_file.hpp"
#include "protocol/device_address.hpp"
#include "view/renderer.hpp"

namespace playerkit::player_view {

using tools::kExitFailure;
using tools::kExitOk;
using tools::kExitUsage;
using tools::UsageError;

// The flags as typed; empty strings and nullopt mean "not given".
struct CommandLine {
  std::vector<std::string> targets;  // [HOST[:PORT]] [DEVICE...]
  std::string snapshot;
  std::optional<double> after;
  std::string record;
  std::optional<double> every;
  std::optional<std::uint64_t> count;
  std::string size = "800x800";
  double span = 12.0;
  std::string map;
  std::optional<double> scale;
  bool negate = false;
  std::optional<std::string> origin;
  std::optional<std::uint16_t> http;
  std::string bind;
  bool drive = false;
  double speed = 0.3;  // m/s
  double turn = 30.0;  // degrees/s
  std::optional<std::string> key;
  double timeout = 5.0;
};

enum class Output { kSnapshot, kRecord, kHttp };

inline constexpr const char* kDefaultBind = "127.0.0.1";

struct ViewOptions {
  client::ServerEndpoint server;
  std::vector<protocol::DeviceAddress> devices;  // empty: every device the server lists
  Output output = Output::kSnapshot;
  std::filesystem::path snapshot;  // --snapshot FILE
  double after = 1.0;              // s of data before the snapshot
  std::filesystem::path record_dir;
  double every = 1.0;                  // s between recorded pictures
  std::optional<std::uint64_t> count;  // pictures to record; none: until a signal
  std::uint16_t http_port = 0;        // --http; 0: a free port, printed
  std::string bind = kDefaultBind;     // --bind
  bool drive = false;                  // the page may drive the robot
  double speed = 0.3;                  // m/s, forward and back
  double turn_rate = 0.5235987755982988;  // rad/s (30 degrees/s)
  view::RenderOptions render;  // pictures only
  std::optional<std::filesystem::path> map;
  map::MapLoadOptions map_loading;
  std::optional<std::string> key;
  double timeout = 5.0;  // s, for connecting and each request
};

inline constexpr double kDefaultAfter = 1.0;
// How often the live page gets a frame.
inline constexpr double kPagesPerSecond = 10.0;

// Throws UsageError.
ViewOptions make_view_options(const CommandLine& command_line);

// "frame-000001.png": the n-th picture --record writes (from 1).
std::string record_file_name(std::uint64_t n);

}  // namespace playerkit::player_view
