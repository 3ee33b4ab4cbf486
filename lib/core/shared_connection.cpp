#include "core/shared_connection.hpp"

#include <stdexcept>
#include <utility>

namespace playerkit::core {

SharedConnection::Use::Use(Use&& other) noexcept
    : connection_(std::exchange(other.connection_, nullptr)) {}

SharedConnection::Use& SharedConnection::Use::operator=(Use&& other) noexcept {
  if (this != &other) {
    release();
    connection_ = std::exchange(other.connection_, nullptr);
  }
  return *this;
}

SharedConnection::Use::~Use() { release(); }

void SharedConnection::Use::release() {
  if (connection_ != nullptr) std::exchange(connection_, nullptr)->detach();
}

SharedConnection::Use SharedConnection::attach() {
  std::lock_guard lock(mutex_);
  if (users_ == 0) open();  // throws: not counted
  ++users_;
  return Use(this);
}

void SharedConnection::detach() noexcept {
  std::lock_guard lock(mutex_);
  if (users_ == 0) return;
  if (--users_ == 0) close();
}

int SharedConnection::users() const {
  std::lock_guard lock(mutex_);
  return users_;
}

std::size_t ConnectionPool::size() const {
  std::lock_guard lock(mutex_);
  return connections_.size();
}

void ConnectionPool::throw_type_clash(const std::string& key) {
  throw std::logic_error("connection '" + key + "' is already used by another kind of driver");
}

}  // namespace playerkit::core
