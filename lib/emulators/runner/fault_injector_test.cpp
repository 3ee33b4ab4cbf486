#include "emulators/runner/fault_injector.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace playerkit::emulators {
namespace fault_injector_test {

const Telegram kTelegram{{0xFA, 0xFB, 0x03, 0x00, 0x00, 0x00}, true};

TEST(FaultInjector, NoPlanLeavesTelegramsAlone) {
  FaultInjector injector({});
  for (int i = 0; i < 100; ++i) {
    const auto chunks = injector.apply(kTelegram);
    ASSERT_EQ(chunks.size(), 1u);
    EXPECT_EQ(chunks[0], kTelegram.bytes);
  }
}

TEST(FaultInjector, ABadChecksumFlipsTheLastByteOnly) {
  FaultInjector injector({.bad_checksum = 1.0});
  const auto chunks = injector.apply(kTelegram);
  ASSERT_EQ(chunks.size(), 1u);
  EXPECT_EQ(std::vector(chunks[0].begin(), chunks[0].end() - 1),
            std::vector(kTelegram.bytes.begin(), kTelegram.bytes.end() - 1));
  EXPECT_NE(chunks[0].back(), kTelegram.bytes.back());
  EXPECT_EQ(injector.counts().bad_checksums, 1u);
  // A byte without a checksum (the SICK ACK) is left alone.
  const auto ack = injector.apply(Telegram{{0x06}, false});
  EXPECT_EQ(ack.at(0), std::vector<std::uint8_t>{0x06});
}

TEST(FaultInjector, GarbageComesBeforeTheTelegramInItsOwnWrite) {
  FaultInjector injector({.garbage = 1.0});
  const auto chunks = injector.apply(kTelegram);
  ASSERT_EQ(chunks.size(), 2u);
  EXPECT_GE(chunks[0].size(), 1u);
  EXPECT_LE(chunks[0].size(), 16u);
  EXPECT_EQ(chunks[1], kTelegram.bytes);
}

TEST(FaultInjector, TruncationKeepsAProperPrefix) {
  FaultInjector injector({.truncate = 1.0});
  for (int i = 0; i < 50; ++i) {
    const auto chunks = injector.apply(kTelegram);
    ASSERT_EQ(chunks.size(), 1u);
    ASSERT_GE(chunks[0].size(), 1u);
    ASSERT_LT(chunks[0].size(), kTelegram.bytes.size());
    EXPECT_TRUE(std::equal(chunks[0].begin(), chunks[0].end(), kTelegram.bytes.begin()));
  }
  EXPECT_EQ(injector.counts().truncated, 50u);
}

bool is_subsequence(const std::vector<std::uint8_t>& part, const std::vector<std::uint8_t>& whole) {
  auto at = whole.begin();
  for (const std::uint8_t byte : part) {
    at = std::find(at, whole.end(), byte);
    if (at == whole.end()) return false;
    ++at;
  }
  return true;
}

TEST(FaultInjector, DroppedBytesGoMissingOneByOne) {
  FaultInjector injector({.drop = 0.5, .seed = 11});
  std::size_t sent = 0, arrived = 0;
  for (int i = 0; i < 200; ++i) {
    for (const auto& chunk : injector.apply(kTelegram)) {
      EXPECT_FALSE(chunk.empty()) << "a telegram that lost every byte is no write at all";
      EXPECT_TRUE(is_subsequence(chunk, kTelegram.bytes)) << "what is left is the telegram with holes, in order";
      arrived += chunk.size();
    }
    sent += kTelegram.bytes.size();
  }
  EXPECT_EQ(injector.counts().dropped_bytes, sent - arrived);
  // Half of 1200 bytes, give or take far more than chance allows.
  EXPECT_GT(arrived, 400u);
  EXPECT_LT(arrived, 800u);
  EXPECT_EQ(FaultInjector({.drop = 1.0}).apply(kTelegram).size(), 0u);
}

TEST(FaultInjector, CountsReadAsOneLine) {
  EXPECT_EQ(describe(InjectedFaults{}), "");
  EXPECT_EQ(describe(InjectedFaults{.bad_checksums = 2, .dropped_bytes = 7}), "2 bad checksums, 7 bytes dropped");
}

TEST(FaultInjector, TheSameSeedGivesTheSameFaults) {
  const FaultPlan plan{.bad_checksum = 0.3, .garbage = 0.3, .truncate = 0.3, .drop = 0.1, .seed = 7};
  FaultInjector a(plan), b(plan);
  for (int i = 0; i < 200; ++i) ASSERT_EQ(a.apply(kTelegram), b.apply(kTelegram));
  const auto& counts = a.counts();
  // With probability 0.3 each, 200 telegrams see every kind many times.
  EXPECT_GT(counts.bad_checksums, 30u);
  EXPECT_GT(counts.garbage_runs, 30u);
  EXPECT_GT(counts.truncated, 30u);
}

}  // namespace fault_injector_test
}  // namespace playerkit::emulators
