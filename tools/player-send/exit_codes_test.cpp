#include "exit_codes.hpp"

#include <gtest/gtest.h>

namespace playerkit::player_send {
namespace exit_codes_test {

using protocol::MessageType;

TEST(ExitCodes, EachReplyTypeHasItsOwnCode) {
  EXPECT_EQ(to_int(exit_code_for_reply(MessageType::kAck)), 0);
  EXPECT_EQ(to_int(exit_code_for_reply(MessageType::kNack)), 3);
  EXPECT_EQ(to_int(exit_code_for_reply(MessageType::kError)), 4);
}

TEST(ExitCodes, AMessageThatIsNotAReplyIsABrokenConversation) {
  EXPECT_EQ(exit_code_for_reply(MessageType::kData), ExitCode::kConnection);
  EXPECT_EQ(exit_code_for_reply(MessageType::kSynch), ExitCode::kConnection);
}

TEST(ExitCodes, UsageAndConnectionCodesAreDistinct) {
  EXPECT_EQ(to_int(ExitCode::kConnection), 1);
  EXPECT_EQ(to_int(ExitCode::kUsage), 2);
}

TEST(ExitCodes, TheFirstFailureOfARunWins) {
  EXPECT_EQ(combine(ExitCode::kAck, ExitCode::kAck), ExitCode::kAck);
  EXPECT_EQ(combine(ExitCode::kAck, ExitCode::kNack), ExitCode::kNack);
  EXPECT_EQ(combine(ExitCode::kNack, ExitCode::kAck), ExitCode::kNack);
  EXPECT_EQ(combine(ExitCode::kNack, ExitCode::kError), ExitCode::kNack);
  EXPECT_EQ(combine(ExitCode::kError, ExitCode::kNack), ExitCode::kError);
}

}  // namespace exit_codes_test
}  // namespace playerkit::player_send
