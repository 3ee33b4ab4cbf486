#include "server/push_schedule.hpp"

#include <gtest/gtest.h>

#include <boost/asio/io_context.hpp>

namespace playerkit::server {
namespace push_schedule_test {

using Clock = PushSchedule::Clock;
using namespace std::chrono_literals;

// Records each call as "name:generation"; may add itself again or stop the loop.
struct Recorder final : PushTarget {
  Recorder(std::string name, std::vector<std::string>& calls) : name(std::move(name)), calls(calls) {}
  void push_due(std::uint64_t generation) override {
    calls.push_back(name + ":" + std::to_string(generation));
    if (on_call) on_call(generation);
  }
  std::string name;
  std::vector<std::string>& calls;
  std::function<void(std::uint64_t)> on_call;
};

struct PushScheduleTest : ::testing::Test {
  std::shared_ptr<Recorder> make(const std::string& name) { return std::make_shared<Recorder>(name, calls); }
  // Runs the loop until it has nothing left or 5 s pass (a bound, not a measurement).
  void run() { io.run_for(5s); }

  boost::asio::io_context io;
  PushSchedule schedule{io.get_executor()};
  std::vector<std::string> calls;
};

TEST_F(PushScheduleTest, CallsEveryTargetOnceInDueOrderTiesInTheOrderAdded) {
  const auto now = Clock::now();
  auto a = make("a");
  auto b = make("b");
  auto c = make("c");
  schedule.add(now + 3ms, a, 1);
  schedule.add(now + 1ms, b, 2);
  schedule.add(now + 3ms, c, 3);
  schedule.add(now + 2ms, a, 4);
  EXPECT_EQ(schedule.pending(), 4u);
  run();
  EXPECT_EQ(calls, (std::vector<std::string>{"b:2", "a:4", "a:1", "c:3"}));
  EXPECT_EQ(schedule.pending(), 0u);
}

TEST_F(PushScheduleTest, RoundsDueWithinTheGatheringWindowGoOutOnTheSameWakeUp) {
  const auto now = Clock::now();
  auto first = make("first");
  auto soon = make("soon");
  auto later = make("later");
  schedule.add(now, first, 1);
  schedule.add(now + PushSchedule::kGatherWithin / 2, soon, 2);
  schedule.add(now + 50 * PushSchedule::kGatherWithin, later, 3);
  io.run_one();  // one handler: the timer's wake-up
  EXPECT_EQ(calls, (std::vector<std::string>{"first:1", "soon:2"}));
  EXPECT_EQ(schedule.pending(), 1u);
  run();
  EXPECT_EQ(calls.back(), "later:3");
}

TEST_F(PushScheduleTest, ATargetGoneByItsTurnIsSkipped) {
  auto kept = make("kept");
  auto gone = make("gone");
  schedule.add(Clock::now(), gone, 1);
  schedule.add(Clock::now(), kept, 2);
  gone.reset();
  run();
  EXPECT_EQ(calls, (std::vector<std::string>{"kept:2"}));
}

TEST_F(PushScheduleTest, AnEarlierEntryDoesNotWaitForTheLaterOneBeingWaitedFor) {
  auto late = make("late");
  auto early = make("early");
  early->on_call = [this](std::uint64_t) { io.stop(); };
  schedule.add(Clock::now() + 1h, late, 1);
  schedule.add(Clock::now(), early, 2);
  run();
  EXPECT_EQ(calls, (std::vector<std::string>{"early:2"}));
  EXPECT_EQ(schedule.pending(), 1u);
}

TEST_F(PushScheduleTest, ATargetThatAddsItsNextRoundFromItsCallIsCalledAgainLater) {
  auto target = make("t");
  int rounds = 0;
  target->on_call = [&](std::uint64_t generation) {
    if (++rounds < 3) schedule.add(Clock::now() + 1ms, target, generation);
  };
  schedule.add(Clock::now(), target, 7);
  run();
  EXPECT_EQ(calls, (std::vector<std::string>{"t:7", "t:7", "t:7"}));
}

TEST_F(PushScheduleTest, ClearDropsEverythingAndTheLoopRunsOut) {
  auto target = make("t");
  schedule.add(Clock::now() + 1h, target, 1);
  schedule.clear();
  EXPECT_EQ(schedule.pending(), 0u);
  io.poll();  // the cancelled wait's handler runs; no timer is left waiting
  EXPECT_TRUE(io.stopped()) << "the schedule still waits on its timer";
  EXPECT_TRUE(calls.empty());
}

}  // namespace push_schedule_test
}  // namespace playerkit::server
