#include "core/reader_progress.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

namespace playerkit::core {
namespace reader_progress_test {

using namespace std::chrono_literals;

TEST(ReaderProgress, NoReadersMeansEverythingIsTaken) {
  ReaderProgress progress;
  std::stop_source never;
  EXPECT_TRUE(progress.wait_until_taken(1000, never.get_token()));
  EXPECT_EQ(progress.count(), 0u);
}

TEST(ReaderProgress, WaitsForTheSlowestReader) {
  ReaderProgress progress;
  progress.taken(1, 5);
  progress.taken(2, 3);
  std::atomic<bool> done{false};
  std::jthread waiter([&](std::stop_token stop) {
    EXPECT_TRUE(progress.wait_until_taken(5, stop));
    done = true;
  });
  std::this_thread::sleep_for(20ms);
  EXPECT_FALSE(done);  // reader 2 is at 3
  progress.taken(2, 4);
  std::this_thread::sleep_for(20ms);
  EXPECT_FALSE(done);
  progress.taken(2, 5);
  waiter.join();
  EXPECT_TRUE(done);
}

TEST(ReaderProgress, AReaderThatLeavesNoLongerHoldsThePublisher) {
  ReaderProgress progress;
  progress.taken(1, 0);
  std::jthread waiter([&](std::stop_token stop) { EXPECT_TRUE(progress.wait_until_taken(9, stop)); });
  std::this_thread::sleep_for(10ms);
  progress.forget(1);
  waiter.join();
  EXPECT_EQ(progress.count(), 0u);
}

TEST(ReaderProgress, StopEndsEveryWait) {
  ReaderProgress progress;
  progress.taken(1, 0);
  std::stop_source stop;
  std::jthread stopper([&] {
    std::this_thread::sleep_for(10ms);
    stop.request_stop();
  });
  EXPECT_FALSE(progress.wait_until_taken(1, stop.get_token()));
  ReaderProgress empty;
  std::stop_source stopped;
  stopped.request_stop();
  EXPECT_FALSE(empty.wait_for_reader(stopped.get_token()));
}

TEST(ReaderProgress, WaitForReaderReturnsOnceOneRegisters) {
  ReaderProgress progress;
  std::jthread registrar([&] {
    std::this_thread::sleep_for(10ms);
    progress.taken(7, 0);
  });
  std::stop_source never;
  EXPECT_TRUE(progress.wait_for_reader(never.get_token()));
  EXPECT_EQ(progress.count(), 1u);
}

}  // namespace reader_progress_test
}  // namespace playerkit::core
