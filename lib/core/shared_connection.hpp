#pragma once
// One hardware connection, many devices. A Pioneer is eleven devices on one
// serial line (p2os_position, p2os_sonar, ...); an RFLEX robot seven; a reb
// three. Each device's driver holds a SharedConnection::Use while it is set
// up: the first Use opens the connection, the last one to go closes it. The
// connection itself is made once per robot and found by the drivers of its
// devices through the ConnectionPool of the device table.
//
//   class P2osConnection : public core::SharedConnection { ... };
//   auto robot = context.connections.get<P2osConnection>(
//       "p2os " + port, [&] { return std::make_shared<P2osConnection>(port); });
//   void setup() override { use_ = robot->attach(); }  // opens on the first
//   void shutdown() override { use_ = {}; }             // closes after the last

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <typeindex>

namespace playerkit::core {

class SharedConnection {
 public:
  SharedConnection() = default;
  SharedConnection(const SharedConnection&) = delete;
  SharedConnection& operator=(const SharedConnection&) = delete;
  virtual ~SharedConnection() = default;

  // Held by a device while it is set up. Moving transfers it; destroying or
  // assigning over it lets go.
  class Use {
   public:
    Use() = default;
    Use(Use&& other) noexcept;
    Use& operator=(Use&& other) noexcept;
    Use(const Use&) = delete;
    Use& operator=(const Use&) = delete;
    ~Use();
    [[nodiscard]] explicit operator bool() const { return connection_ != nullptr; }

   private:
    friend class SharedConnection;
    explicit Use(SharedConnection* connection) : connection_(connection) {}
    void release();
    SharedConnection* connection_ = nullptr;
  };

  // Opens the connection for the first user. Throws what open() throws (a
  // DriverError refuses the device's subscription); the failed user is not
  // counted, so the next attach() tries again.
  [[nodiscard]] Use attach();
  [[nodiscard]] int users() const;

 protected:
  // The first user arrived: open the port, handshake, start the I/O thread.
  virtual void open() = 0;
  // The last user left: stop what moves (motors), then close. Must not throw.
  virtual void close() noexcept = 0;

 private:
  void detach() noexcept;

  mutable std::mutex mutex_;  // serialises open/close with the count
  int users_ = 0;
};

// The connections of one device table, by key (e.g. "p2os /dev/ttyS0").
class ConnectionPool {
 public:
  // The connection registered under `key`, made by `make` on first use.
  // Throws std::logic_error when the key is taken by a connection of another
  // type (two driver families claiming one port).
  template <class Connection>
  std::shared_ptr<Connection> get(const std::string& key,
                                  const std::function<std::shared_ptr<Connection>()>& make) {
    std::lock_guard lock(mutex_);
    auto found = connections_.find(key);
    if (found == connections_.end()) {
      std::shared_ptr<Connection> made = make();
      connections_.emplace(key, Entry{made, typeid(Connection)});
      return made;
    }
    if (found->second.type != typeid(Connection)) throw_type_clash(key);
    return std::static_pointer_cast<Connection>(found->second.connection);
  }
  [[nodiscard]] std::size_t size() const;

 private:
  struct Entry {
    std::shared_ptr<SharedConnection> connection;
    std::type_index type;
  };
  [[noreturn]] static void throw_type_clash(const std::string& key);

  mutable std::mutex mutex_;
  std::map<std::string, Entry> connections_;
};

}  // namespace playerkit::core
