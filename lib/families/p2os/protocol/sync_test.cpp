#include "families/p2os/protocol/sync.hpp"

#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "families/p2os/protocol/test_support.hpp"

#include <gtest/gtest.h>

namespace playerkit::hardware::p2os {
namespace sync_test {

using testing::hex;
namespace golden = testing::golden;

TEST(Sync2Reply, EncodesTheWorkedExample) {
  const Sync2Reply reply{.name = "MyRobot", .robot_class = "Pioneer", .subclass = "p3dx"};
  EXPECT_EQ(build_frame(encode_sync2_reply(reply)), hex(golden::sync2_myrobot));
}

TEST(Sync2Reply, DecodesTheWorkedExample) {
  const Sync2Reply reply = decode_sync2_reply(frame_payload(hex(golden::sync2_myrobot)));
  EXPECT_EQ(reply.name, "MyRobot");
  EXPECT_EQ(reply.robot_class, "Pioneer");
  EXPECT_EQ(reply.subclass, "p3dx");
}

TEST(Sync2Reply, RefusesStringsTheReferenceCannotHold) {
  Sync2Reply reply{.name = std::string(19, 'n'), .robot_class = "Pioneer", .subclass = "p3dx"};
  EXPECT_EQ(decode_sync2_reply(encode_sync2_reply(reply)), reply);
  reply.name = std::string(20, 'n');
  EXPECT_THROW(encode_sync2_reply(reply), EncodeError);
  reply.name = std::string("a\0b", 3);
  EXPECT_THROW(encode_sync2_reply(reply), EncodeError);
}

TEST(Sync2Reply, TruncationIsAClearError) {
  const auto frame = hex(golden::sync2_myrobot);
  const auto payload = frame_payload(frame);
  for (std::size_t size = 0; size < payload.size(); ++size) {
    EXPECT_THROW(decode_sync2_reply(payload.first(size)), DecodeError) << "size " << size;
  }
  try {
    decode_sync2_reply(payload.first(payload.size() - 1));
    FAIL();
  } catch (const DecodeError& e) {
    EXPECT_NE(std::string(e.what()).find("subclass"), std::string::npos) << e.what();
  }
}

TEST(Sync2Reply, RejectsOtherTypes) {
  EXPECT_THROW(decode_sync2_reply(hex("01 41 00 42 00 43 00")), DecodeError);
}

}  // namespace sync_test
}  // namespace playerkit::hardware::p2os
