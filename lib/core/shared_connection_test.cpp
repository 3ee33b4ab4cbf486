#include "core/shared_connection.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/driver.hpp"

namespace playerkit::core {
namespace shared_connection_test {

// Records what happens to the line, as a robot's connection would do to a port.
class RecordingConnection : public SharedConnection {
 public:
  explicit RecordingConnection(std::vector<std::string>& events, bool refuse = false)
      : refuse_(refuse), events_(events) {}
  bool refuse_;

 protected:
  void open() override {
    events_.push_back("open");
    if (refuse_) throw DriverError("no robot on /tmp/robot-a");
  }
  void close() noexcept override {
    events_.push_back("stop motors");
    events_.push_back("close");
  }

 private:
  std::vector<std::string>& events_;
};

TEST(SharedConnection, OpensOnTheFirstUserAndClosesAfterTheLast) {
  std::vector<std::string> events;
  RecordingConnection connection(events);
  auto sonar = connection.attach();  // sonar alone opens the line
  EXPECT_EQ(events, std::vector<std::string>{"open"});
  auto position = connection.attach();  // adding position: no second open
  EXPECT_EQ(connection.users(), 2);
  sonar = {};  // dropping sonar keeps the line open for position
  EXPECT_EQ(events, std::vector<std::string>{"open"});
  EXPECT_EQ(connection.users(), 1);
  position = {};  // the last one leaving stops the motors and closes
  EXPECT_EQ(events, (std::vector<std::string>{"open", "stop motors", "close"}));
  EXPECT_EQ(connection.users(), 0);
  auto again = connection.attach();  // and it can be opened again
  EXPECT_EQ(events.back(), "open");
}

TEST(SharedConnection, AFailedOpenIsNotCountedAndTheNextAttachRetries) {
  std::vector<std::string> events;
  RecordingConnection connection(events, true);
  EXPECT_THROW((void)connection.attach(), DriverError);
  EXPECT_EQ(connection.users(), 0);
  connection.refuse_ = false;
  auto use = connection.attach();
  EXPECT_TRUE(use);
  EXPECT_EQ(events, (std::vector<std::string>{"open", "open"}));
}

TEST(SharedConnection, MovingAUseTransfersIt) {
  std::vector<std::string> events;
  RecordingConnection connection(events);
  auto first = connection.attach();
  SharedConnection::Use second = std::move(first);
  EXPECT_FALSE(first);  // NOLINT(bugprone-use-after-move): testing the moved-from state
  EXPECT_EQ(connection.users(), 1);
  second = {};
  EXPECT_EQ(events.back(), "close");
}

TEST(ConnectionPool, OneConnectionPerKey) {
  std::vector<std::string> events;
  ConnectionPool pool;
  int made = 0;
  auto make = [&] {
    ++made;
    return std::make_shared<RecordingConnection>(events);
  };
  auto a = pool.get<RecordingConnection>("p2os /tmp/robot-a", make);
  auto b = pool.get<RecordingConnection>("p2os /tmp/robot-a", make);
  auto c = pool.get<RecordingConnection>("p2os /tmp/robot-b", make);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_EQ(made, 2);
  EXPECT_EQ(pool.size(), 2u);
}

class OtherConnection : public SharedConnection {
  void open() override {}
  void close() noexcept override {}
};

TEST(ConnectionPool, AKeyClaimedByAnotherKindIsAnError) {
  std::vector<std::string> events;
  ConnectionPool pool;
  (void)pool.get<RecordingConnection>("/tmp/robot-a", [&] { return std::make_shared<RecordingConnection>(events); });
  EXPECT_THROW((void)pool.get<OtherConnection>("/tmp/robot-a", [] { return std::make_shared<OtherConnection>(); }),
               std::logic_error);
}

}  // namespace shared_connection_test
}  // namespace playerkit::core
