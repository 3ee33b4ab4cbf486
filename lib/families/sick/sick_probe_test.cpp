// The probe's answers when a reply is late: the laser below answers every
// request at once, as its sheet says (A0 00 to its own password, A0 01 to the
// other's, BA with its type), and can be told to put one late "accepted" on
// the line first: the answer to the other model's password, asked by the
// probe before at the same rate, that came after that probe gave up.

#include "families/sick/sick_probe.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <deque>
#include <string>
#include <vector>

#include "families/sick/protocol/codes.hpp"
#include "families/sick/protocol/replies.hpp"
#include "families/sick/protocol/telegram.hpp"
#include "links/byte_link.hpp"

namespace playerkit::families {
namespace sick_probe_test {

namespace sick = hardware::sick;
using namespace std::chrono_literals;
using Bytes = std::vector<std::uint8_t>;

class AnsweringLaser final : public links::ByteLink {
 public:
  AnsweringLaser(sick::Model model, std::string type) : model_(model), type_(std::move(type)) {}

  // Puts the answer to a password asked before on the line after the next request.
  void answer_late(sick::ModeResult result) { late_ = sick::encode_reply(sick::ModeReply{result}); }

  int requests = 0;

  void flush_input() override { pending_.clear(); }
  void drain() override {}
  void close() noexcept override {}
  [[nodiscard]] bool is_open() const override { return true; }
  void reopen(links::Deadline) override {}
  [[nodiscard]] std::string describe() const override { return "an answering laser"; }
  [[nodiscard]] int native_handle() const override { return -1; }

 protected:
  std::size_t read_available(std::span<std::uint8_t> buffer, links::Deadline) override {
    const std::size_t count = std::min(buffer.size(), pending_.size());
    std::copy_n(pending_.begin(), count, buffer.begin());
    pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(count));
    return count;
  }

  std::size_t write_available(std::span<const std::uint8_t> bytes, links::Deadline) override {
    ++requests;
    if (!late_.empty()) {
      pending_.insert(pending_.end(), late_.begin(), late_.end());
      late_.clear();
    }
    const Bytes answer = answer_to(sick::unframe_request(bytes));
    pending_.insert(pending_.end(), answer.begin(), answer.end());
    return bytes.size();
  }

 private:
  Bytes answer_to(const Bytes& body) const {
    if (body.at(0) == sick::kSwitchModeCommand) {
      const std::string password(body.begin() + 2, body.end());
      const bool mine = password == sick::installation_password(model_);
      return sick::encode_reply(
          sick::ModeReply{mine ? sick::ModeResult::ok : sick::ModeResult::wrong_password});
    }
    if (body.at(0) == sick::kGetTypeCommand) return sick::encode_reply(sick::TypeReply{type_});
    return sick::encode_reply(sick::NotAcknowledgedReply{});
  }

  sick::Model model_;
  std::string type_;
  Bytes late_;
  std::deque<std::uint8_t> pending_;
};

std::optional<Identification> probe(AnsweringLaser& laser, sick::Model first) {
  const ProbeContext line{.link = laser,
                          .baud = 500000,
                          .first_reply = links::deadline_in(2s),
                          .finish = links::deadline_in(2s)};
  return probe_sick(line, first);
}

TEST(SickProbe, FindsAnLmsByItsPasswordAndType) {
  AnsweringLaser laser(sick::Model::lms200, "LMS291-S05");
  const auto found = probe(laser, sick::Model::lms200);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->driver, "sicklms200");
  EXPECT_EQ(found->model, "LMS291-S05");
}

TEST(SickProbe, FindsAPlsAskedTheLmsPasswordFirst) {
  AnsweringLaser laser(sick::Model::pls, "unused");
  const auto found = probe(laser, sick::Model::lms200);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->driver, "sickpls");
  EXPECT_EQ(found->model, "PLS");
}

// The flake CI found: an LMS at 500000 reported as a PLS, because the late
// "accepted" of the LMS password was read as the answer to the PLS one.
TEST(SickProbe, ALateAcceptedForTheOtherPasswordDoesNotMakeAnLmsAPls) {
  AnsweringLaser laser(sick::Model::lms200, "LMS291-S05");
  laser.answer_late(sick::ModeResult::ok);
  const auto found = probe(laser, sick::Model::pls);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->driver, "sicklms200");
  EXPECT_EQ(found->model, "LMS291-S05");
  // PLS password, asked again, LMS password twice, type.
  EXPECT_EQ(laser.requests, 5);
}

TEST(SickProbe, ALateAcceptedForTheOtherPasswordDoesNotMakeAPlsAnLms) {
  AnsweringLaser laser(sick::Model::pls, "unused");
  laser.answer_late(sick::ModeResult::ok);
  const auto found = probe(laser, sick::Model::lms200);
  ASSERT_TRUE(found);
  EXPECT_EQ(found->driver, "sickpls");
}

TEST(SickProbe, AskingAnAcceptedPasswordAgainCostsOneRequest) {
  AnsweringLaser laser(sick::Model::pls, "unused");
  ASSERT_TRUE(probe(laser, sick::Model::pls));
  EXPECT_EQ(laser.requests, 2);
}

}  // namespace sick_probe_test
}  // namespace playerkit::families
