#include "links/trace_format.hpp"

#include <gtest/gtest.h>

#include "links/link_counters.hpp"

namespace playerkit::links {
namespace trace_format_test {

TEST(TraceFormat, HexBytesUpperCaseSpaced) {
  const std::uint8_t bytes[] = {0x02, 0x80, 0x03, 0x00, 0xA0, 0x00, 0x10, 0x16, 0x0A};
  EXPECT_EQ(hex_bytes(bytes), "02 80 03 00 A0 00 10 16 0A");
  EXPECT_EQ(hex_bytes({}), "");
}

TEST(TraceFormat, LineShowsDirectionAndTime) {
  const std::uint8_t bytes[] = {0xFA, 0xFB};
  EXPECT_EQ(format_trace_line("lms", Direction::out, bytes, std::chrono::microseconds(12345)),
            "lms     0.012345 > FA FB");
  EXPECT_EQ(format_trace_line("lms", Direction::in, bytes, std::chrono::seconds(2)), "lms     2.000000 < FA FB");
}

TEST(TraceFormat, HookHandsOneLinePerCall) {
  std::vector<std::string> lines;
  const TraceHook hook = hex_trace_hook("p", [&](std::string_view line) { lines.emplace_back(line); });
  const std::uint8_t bytes[] = {0x01};
  hook(Direction::out, bytes, LinkClock::now());
  hook(Direction::in, bytes, LinkClock::now());
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find(" > 01"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find(" < 01"), std::string::npos) << lines[1];
}

TEST(LinkCounters, SnapshotDifferenceAndText) {
  LinkCounters counters;
  counters.bytes_in.add(100);
  const LinkCounterSnapshot before = counters.snapshot();
  counters.bytes_in.add(20);
  counters.telegrams.add();
  counters.checksum_errors.add();
  counters.resyncs.add(2);
  counters.bytes_dropped.add(7);
  const LinkCounterSnapshot change = counters.snapshot() - before;
  EXPECT_EQ(change.bytes_in, 20u);
  EXPECT_EQ(change.telegrams, 1u);
  EXPECT_EQ(to_string(change),
            "in 20 B, out 0 B, 1 telegram, 1 checksum error, 2 resyncs (7 B dropped), 0 timeouts, 0 reconnects, 0 retries");
}

}  // namespace trace_format_test
}  // namespace playerkit::links
