#include "links/framed_reader.hpp"

#include <gtest/gtest.h>

#include <deque>

#include "links/link_error.hpp"
#include "links/links_test_support.hpp"
#include "links/serial_link.hpp"

namespace playerkit::links {
namespace framed_reader_test {

using namespace test_support;

// A toy protocol for the reader: AA, N, N payload bytes, XOR of the payload.
// `trusted_length` is the longest N it believes; the lax variant believes
// anything, to see the reader protect itself from a corrupted length.
class XorFormat final : public framing::FrameFormat {
 public:
  explicit XorFormat(std::size_t trusted_length = 32) : trusted_length_(trusted_length) {}
  [[nodiscard]] std::string_view name() const override { return "toy-xor"; }
  [[nodiscard]] framing::FrameScan scan(std::span<const std::uint8_t> buffered) const override {
    if (buffered[0] != 0xAA) {
      std::size_t noise = 1;
      while (noise < buffered.size() && buffered[noise] != 0xAA) ++noise;
      return framing::FrameScan::noise(noise);
    }
    if (buffered.size() < 2) return framing::FrameScan::need(2);
    const std::size_t payload = buffered[1];
    if (payload > trusted_length_) return framing::FrameScan::noise(1);
    const std::size_t size = payload + 3;
    if (buffered.size() < size) return framing::FrameScan::need(size);
    std::uint8_t check = 0;
    for (std::size_t i = 2; i < size - 1; ++i) check ^= buffered[i];
    return check == buffered[size - 1] ? framing::FrameScan::whole(size) : framing::FrameScan::corrupt(size);
  }

 private:
  std::size_t trusted_length_;
};

// Never decides: the reader must still bound its buffer.
class UndecidedFormat final : public framing::FrameFormat {
 public:
  [[nodiscard]] std::string_view name() const override { return "undecided"; }
  [[nodiscard]] framing::FrameScan scan(std::span<const std::uint8_t>) const override {
    return framing::FrameScan::need();
  }
};

// Delivers scripted chunks, one per read; an empty script reads as a timeout.
class ScriptedLink final : public ByteLink {
 public:
  void arrive(Bytes chunk) { chunks_.push_back(std::move(chunk)); }
  void disconnect_after_script() { disconnect_ = true; }
  int flushes = 0;

  void flush_input() override {
    ++flushes;
    chunks_.clear();
  }
  void drain() override {}
  void close() noexcept override {}
  [[nodiscard]] bool is_open() const override { return true; }
  void reopen(Deadline) override {}
  [[nodiscard]] std::string describe() const override { return "script"; }
  [[nodiscard]] int native_handle() const override { return -1; }

 protected:
  std::size_t read_available(std::span<std::uint8_t> buffer, Deadline) override {
    if (chunks_.empty()) {
      if (disconnect_) throw LinkError(LinkErrorKind::disconnected, "script", "script: gone");
      return 0;
    }
    Bytes& chunk = chunks_.front();
    const std::size_t count = std::min(buffer.size(), chunk.size());
    std::copy_n(chunk.begin(), count, buffer.begin());
    chunk.erase(chunk.begin(), chunk.begin() + static_cast<std::ptrdiff_t>(count));
    if (chunk.empty()) chunks_.pop_front();
    return count;
  }
  std::size_t write_available(std::span<const std::uint8_t> bytes, Deadline) override { return bytes.size(); }

 private:
  std::deque<Bytes> chunks_;
  bool disconnect_ = false;
};

struct Fixture {
  ScriptedLink link;
  XorFormat format;
  FramedReader reader{link, format, 64};

  std::optional<Bytes> next() { return reader.next(deadline_in(kPatience)); }
  LinkCounterSnapshot counters() const { return link.counters().snapshot(); }
};

TEST(FramedReader, WholeTelegram) {
  Fixture f;
  f.link.arrive({0xAA, 0x02, 0x01, 0x02, 0x03});
  EXPECT_EQ(f.next(), (Bytes{0xAA, 0x02, 0x01, 0x02, 0x03}));
  EXPECT_EQ(f.counters().telegrams, 1u);
  EXPECT_EQ(f.counters().bytes_dropped, 0u);
}

TEST(FramedReader, TelegramSplitAcrossReads) {
  Fixture f;
  f.link.arrive({0xAA});
  f.link.arrive({0x02, 0x01});
  f.link.arrive({0x02});
  f.link.arrive({0x03});
  EXPECT_EQ(f.next(), (Bytes{0xAA, 0x02, 0x01, 0x02, 0x03}));
}

TEST(FramedReader, MergedTelegramsComeOneByOne) {
  Fixture f;
  f.link.arrive({0xAA, 0x01, 0x05, 0x05, 0xAA, 0x00, 0x00, 0xAA, 0x01});
  f.link.arrive({0x07, 0x07});
  EXPECT_EQ(f.next(), (Bytes{0xAA, 0x01, 0x05, 0x05}));
  EXPECT_EQ(f.next(), (Bytes{0xAA, 0x00, 0x00}));
  EXPECT_EQ(f.next(), (Bytes{0xAA, 0x01, 0x07, 0x07}));
  EXPECT_EQ(f.counters().telegrams, 3u);
}

TEST(FramedReader, GarbageBeforeATelegramIsOneResync) {
  Fixture f;
  f.link.arrive({0x11, 0x22, 0x33});
  f.link.arrive({0x44, 0xAA, 0x01, 0x05, 0x05});
  EXPECT_EQ(f.next(), (Bytes{0xAA, 0x01, 0x05, 0x05}));
  EXPECT_EQ(f.counters().resyncs, 1u);
  EXPECT_EQ(f.counters().bytes_dropped, 4u);
}

TEST(FramedReader, BadChecksumIsDroppedAndCounted) {
  Fixture f;
  f.link.arrive({0xAA, 0x01, 0x05, 0x06, 0xAA, 0x01, 0x07, 0x07});
  EXPECT_EQ(f.next(), (Bytes{0xAA, 0x01, 0x07, 0x07}));
  const auto counters = f.counters();
  EXPECT_EQ(counters.checksum_errors, 1u);
  EXPECT_EQ(counters.resyncs, 0u);
  EXPECT_EQ(counters.bytes_dropped, 4u);
  EXPECT_EQ(counters.telegrams, 1u);
}

TEST(FramedReader, CorruptedLengthDoesNotSwallowTheNextTelegram) {
  ScriptedLink link;
  const XorFormat lax(255);
  FramedReader reader(link, lax, 64);
  // 0x05 was meant to be 0x01: the bogus span covers a real telegram.
  link.arrive({0xAA, 0x05, 0x09, 0x09});
  link.arrive({0xAA, 0x01, 0x07, 0x07, 0x11});
  EXPECT_EQ(reader.next(deadline_in(kPatience)), (Bytes{0xAA, 0x01, 0x07, 0x07}));
  EXPECT_EQ(link.counters().snapshot().checksum_errors, 1u);
}

TEST(FramedReader, AbsurdLengthIsNoiseNotAWait) {
  ScriptedLink link;
  const XorFormat lax(255);
  FramedReader reader(link, lax, 16);  // nothing longer than 16 bytes exists
  link.arrive({0xAA, 0xF0, 0x01, 0x02});
  link.arrive({0xAA, 0x01, 0x07, 0x07});
  EXPECT_EQ(reader.next(deadline_in(kPatience)), (Bytes{0xAA, 0x01, 0x07, 0x07}));
  EXPECT_EQ(link.counters().snapshot().resyncs, 1u);
}

TEST(FramedReader, UndecidedFormatCannotGrowTheBuffer) {
  ScriptedLink link;
  const UndecidedFormat format;
  FramedReader reader(link, format, 16);
  for (int i = 0; i < 10; ++i) link.arrive(Bytes(10, 0x55));
  EXPECT_EQ(reader.next(deadline_in(kPatience)), std::nullopt);
  EXPECT_LT(reader.buffered(), 16u);
  EXPECT_EQ(link.counters().snapshot().bytes_dropped + reader.buffered(), 100u);
}

TEST(FramedReader, TimeoutKeepsThePartialTelegram) {
  Fixture f;
  f.link.arrive({0xAA, 0x02, 0x01});
  EXPECT_EQ(f.next(), std::nullopt);
  EXPECT_EQ(f.counters().timeouts, 1u);
  EXPECT_EQ(f.reader.buffered(), 3u);
  f.link.arrive({0x02, 0x03});
  EXPECT_EQ(f.next(), (Bytes{0xAA, 0x02, 0x01, 0x02, 0x03}));
}

TEST(FramedReader, FlushDropsPartialAndPendingInput) {
  Fixture f;
  f.link.arrive({0xAA, 0x02, 0x01});
  EXPECT_EQ(f.next(), std::nullopt);
  f.link.arrive({0x02, 0x03});
  f.reader.flush();
  EXPECT_EQ(f.link.flushes, 1);
  EXPECT_EQ(f.reader.buffered(), 0u);
  f.link.arrive({0xAA, 0x00, 0x00});
  EXPECT_EQ(f.next(), (Bytes{0xAA, 0x00, 0x00}));
}

TEST(FramedReader, LinkErrorsPassThrough) {
  Fixture f;
  f.link.arrive({0xAA, 0x01});
  f.link.disconnect_after_script();
  try {
    f.next();
    FAIL();
  } catch (const LinkError& error) {
    EXPECT_EQ(error.kind(), LinkErrorKind::disconnected);
  }
}

TEST(FramedReader, NoiseBadChecksumsAndSplitsOverARealPty) {
  PseudoTerminal pty;
  auto link = SerialLink::open(pty.path(), {.baud = 38400});
  const XorFormat format;
  FramedReader reader(*link, format, 64);
  const std::vector<Bytes> pieces = {
      {0x00, 0xFF, 0x13},                    // line noise
      {0xAA, 0x03, 0x10},                    // first half of a telegram
      {0x20, 0x30, 0x00},                    // its second half (0x10^0x20^0x30 = 0x00)
      {0xAA, 0x01, 0x44, 0x45},              // bad checksum
      {0xAA, 0x01, 0x44, 0x44, 0xAA, 0x00},  // one whole and the start of the next
      {0x00},
  };
  for (const auto& piece : pieces) ASSERT_TRUE(pty.write_all(piece, deadline_in(kPatience)));
  EXPECT_EQ(reader.next(deadline_in(kPatience)), (Bytes{0xAA, 0x03, 0x10, 0x20, 0x30, 0x00}));
  EXPECT_EQ(reader.next(deadline_in(kPatience)), (Bytes{0xAA, 0x01, 0x44, 0x44}));
  EXPECT_EQ(reader.next(deadline_in(kPatience)), (Bytes{0xAA, 0x00, 0x00}));
  EXPECT_EQ(reader.next(deadline_in(20ms)), std::nullopt);
  const auto counters = link->counters().snapshot();
  EXPECT_EQ(counters.telegrams, 3u);
  EXPECT_EQ(counters.checksum_errors, 1u);
  EXPECT_EQ(counters.resyncs, 1u);
  EXPECT_EQ(counters.timeouts, 1u);
  EXPECT_EQ(counters.bytes_dropped, 3u + 4u);
}

}  // namespace framed_reader_test
}  // namespace playerkit::links
