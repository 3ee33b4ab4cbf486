#pragma once
// A driver's configuration request to a device it is built on (lasercspace
// passing GET_GEOM on to its laser, a planner asking its position device),
// served as a client's would be: queued on the device, answered by its driver
// on the driver's own thread or on the server's loop, and the reply handed
// back to the one asking instead of to the server.
//
// Blocks until the reply or the timeout. Call it from a driver's own thread
// (a ThreadedDriver): on the server's loop it would wait for the very loop
// that answers a loop-driven source.

#include <chrono>
#include <cstdint>
#include <optional>
#include <vector>

#include "core/device.hpp"

namespace playerkit::core {

// nullopt when the device's request queue is full or no reply came in time
// (a late reply is dropped, never delivered to anyone else).
std::optional<Reply> ask_source(Device& source, std::vector<std::uint8_t> payload,
                                std::chrono::milliseconds timeout);

}  // namespace playerkit::core
