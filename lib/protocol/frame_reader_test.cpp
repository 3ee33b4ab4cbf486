#include "protocol/frame_reader.hpp"

#include <gtest/gtest.h>

#include "protocol/interfaces.hpp"

namespace playerkit::protocol {
namespace frame_reader_test {



std::vector<std::uint8_t> request_bytes(std::vector<std::uint8_t> payload,
                                        std::uint16_t device = kPlayerCode) {
  return encode_message(
      make_header(MessageType::kRequest, {device, 0}, {}, {}), payload);
}

std::vector<std::uint8_t> concat(std::initializer_list<std::vector<std::uint8_t>> parts) {
  std::vector<std::uint8_t> all;
  for (const auto& part : parts) all.insert(all.end(), part.begin(), part.end());
  return all;
}

TEST(FrameReaderTest, SplitsBackToBackMessages) {
  FrameReader reader;
  const auto bytes = concat({request_bytes({0, 1}), request_bytes({0, 6, 0, 20})});
  const auto events = reader.feed(bytes);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(std::get<Message>(events[0]).payload, (std::vector<std::uint8_t>{0, 1}));
  EXPECT_EQ(std::get<Message>(events[1]).payload, (std::vector<std::uint8_t>{0, 6, 0, 20}));
  EXPECT_EQ(reader.buffered(), 0u);
}

TEST(FrameReaderTest, WaitsForTheRestOfAMessageFedOneByteAtATime) {
  FrameReader reader;
  const auto bytes = request_bytes({0, 3, 0, 6, 0, 0, 'r'});
  std::vector<FrameEvent> events;
  for (std::uint8_t byte : bytes) {
    auto more = reader.feed(std::span<const std::uint8_t>(&byte, 1));
    events.insert(events.end(), more.begin(), more.end());
  }
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(std::get<Message>(events[0]).header.size, 7u);
}

TEST(FrameReaderTest, SkipsGarbageToTheNextMarkerAndReportsItOnce) {
  FrameReader reader;
  const auto bytes = concat({{'h', 'e', 'l', 'l', 'o', 'X'}, request_bytes({0, 1})});
  const auto events = reader.feed(bytes);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(std::get<SkippedBytes>(events[0]).count, 6u);
  EXPECT_EQ(std::get<Message>(events[1]).payload, (std::vector<std::uint8_t>{0, 1}));
}

TEST(FrameReaderTest, KeepsAHalfMarkerAtTheEndOfAChunk) {
  FrameReader reader;
  const auto message = request_bytes({0, 1});
  std::vector<std::uint8_t> first{'z', 'z', 'X'};
  std::vector<std::uint8_t> second(message.begin() + 1, message.end());
  auto events = reader.feed(first);
  ASSERT_TRUE(events.empty());  // the garbage count waits for the next message
  events = reader.feed(second);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(std::get<SkippedBytes>(events[0]).count, 2u);
  EXPECT_TRUE(std::holds_alternative<Message>(events[1]));
}

TEST(FrameReaderTest, OversizeMessageIsReportedAndItsBodySkipped) {
  FrameReader reader;
  std::vector<std::uint8_t> big_payload(kMaxPayloadSize + 1, 'X');  // markers inside!
  const auto bytes = concat({request_bytes(big_payload, kLaserCode), request_bytes({0, 1})});
  const auto events = reader.feed(bytes);
  ASSERT_EQ(events.size(), 2u);
  const auto& oversize = std::get<OversizeMessage>(events[0]);
  EXPECT_EQ(oversize.header.size, kMaxPayloadSize + 1);
  EXPECT_EQ(oversize.header.device, kLaserCode);
  EXPECT_EQ(std::get<Message>(events[1]).payload, (std::vector<std::uint8_t>{0, 1}));
}

TEST(FrameReaderTest, AbsurdSizeIsTreatedAsGarbage) {
  FrameReader reader;
  auto header = make_header(MessageType::kRequest, {1, 0}, {}, {});
  header.size = 0xFFFFFFF0;
  const auto header_bytes = encode_header(header);
  const auto bytes = concat({{header_bytes.begin(), header_bytes.end()}, request_bytes({0, 1})});
  const auto events = reader.feed(bytes);
  ASSERT_EQ(events.size(), 2u);
  EXPECT_EQ(std::get<SkippedBytes>(events[0]).count, kHeaderSize);
  EXPECT_EQ(std::get<Message>(events[1]).payload, (std::vector<std::uint8_t>{0, 1}));
}

}  // namespace frame_reader_test
}  // namespace playerkit::protocol

namespace playerkit::protocol {
namespace frame_reader_test {

TEST(FrameReaderTest, AReaderMayAllowLargerPayloads) {
  const std::vector<std::uint8_t> image(100'000, 7);  // a camera frame, say
  const auto bytes =
      encode_message(make_header(MessageType::kData, {kCameraCode, 0}, {}, {}), image);
  FrameReader strict;
  EXPECT_TRUE(std::holds_alternative<OversizeMessage>(strict.feed(bytes).front()));
  FrameReader roomy(1 << 20);
  const auto events = roomy.feed(bytes);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(std::get<Message>(events[0]).payload, image);
}

}  // namespace frame_reader_test
}  // namespace playerkit::protocol
