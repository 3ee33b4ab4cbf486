// Encode/decode throughput of a whole laser data message (32-byte header plus the
// 1213-byte player_laser_data_t), the message a server sends most of.
//
//   ./build/bench/protocol_bench --benchmark_counters_tabular=true
//
// items_per_second is messages per second on one core.

#include <benchmark/benchmark.h>

#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message.hpp"
#include "protocol/message_json.hpp"
#include "protocol/messages/laser.hpp"

namespace playerkit::protocol {
namespace {

LaserData sample_scan() {
  LaserData scan;
  scan.min_angle = -9000;
  scan.max_angle = 9000;
  scan.resolution = 50;
  scan.range_res = 1;
  scan.range_count = 361;
  for (std::size_t i = 0; i < scan.range_count; ++i) {
    scan.ranges[i] = static_cast<std::uint16_t>(500 + 37 * i % 8000);
    scan.intensity[i] = static_cast<std::uint8_t>(i % 3);
  }
  return scan;
}

MessageHeader laser_header() {
  return make_header(MessageType::kData, {kLaserCode, 0}, {1086000000, 250000}, {1086000000, 200000});
}

void BM_EncodeLaserMessage(benchmark::State& state) {
  const LaserData scan = sample_scan();
  const MessageHeader header = laser_header();
  std::vector<std::uint8_t> wire;
  wire.reserve(kHeaderSize + LaserData::kWireSize);
  for (auto _ : state) {
    wire.clear();
    wire.resize(kHeaderSize);
    encode_to(scan, wire);
    MessageHeader h = header;
    h.size = static_cast<std::uint32_t>(wire.size() - kHeaderSize);
    const auto head = encode_header(h);
    std::copy(head.begin(), head.end(), wire.begin());
    benchmark::DoNotOptimize(wire.data());
  }
  state.SetItemsProcessed(state.iterations());
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(kHeaderSize + LaserData::kWireSize));
}
BENCHMARK(BM_EncodeLaserMessage);

void BM_DecodeLaserMessage(benchmark::State& state) {
  MessageHeader header = laser_header();
  const auto wire = encode_message(header, encode(sample_scan()));
  for (auto _ : state) {
    const MessageHeader h = decode_header(std::span(wire).first<kHeaderSize>());
    const LaserData scan = decode<LaserData>(std::span(wire).subspan(kHeaderSize, h.size));
    benchmark::DoNotOptimize(scan.ranges.data());
  }
  state.SetItemsProcessed(state.iterations());
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(wire.size()));
}
BENCHMARK(BM_DecodeLaserMessage);

// What `player-cat --format json` pays per scan.
void BM_LaserMessageToJson(benchmark::State& state) {
  Message message;
  message.header = laser_header();
  message.payload = encode(sample_scan());
  message.header.size = static_cast<std::uint32_t>(message.payload.size());
  for (auto _ : state) {
    const std::string text = message_to_json(message).dump();
    benchmark::DoNotOptimize(text.data());
  }
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_LaserMessageToJson);

}  // namespace
}  // namespace playerkit::protocol

BENCHMARK_MAIN();
