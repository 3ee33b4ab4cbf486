#include "core/device.hpp"

#include <algorithm>
#include <exception>
#include <thread>
#include <utility>

#include "protocol/catalog.hpp"

namespace playerkit::core {

using protocol::Access;

std::string to_string(const DeviceKey& key) {
  return protocol::to_string(key.address) + "@" + std::to_string(key.port);
}

Device::Device(DeviceKey key, DeviceInfo info, std::unique_ptr<Driver> driver,
               const Clock& clock, Logger& logger)
    : key_(key),
      info_(std::move(info)),
      driver_(std::move(driver)),
      clock_(clock),
      logger_(logger),
      data_(std::make_shared<const DataSample>()) {
  driver_->device_ = this;
  if (const auto* messages = protocol::find_messages(key_.address.interface);
      messages != nullptr && messages->command != nullptr) {
    command_min_size_ = messages->command->min_size;
    command_max_size_ = messages->command->max_size;
  }
}

Device::~Device() { force_shutdown(); }

std::string Device::name() const { return to_string(key_) + " (" + info_.driver_name + ")"; }

bool Device::readable() const { return info_.access == Access::kRead || info_.access == Access::kAll; }

bool Device::writable() const { return info_.access == Access::kWrite || info_.access == Access::kAll; }

bool Device::subscribe() {
  std::lock_guard lock(subscription_mutex_);
  if (subscriptions_ == 0) {
    finish_background_shutdown();
    set_available(true);
    try {
      driver_->setup();
    } catch (const std::exception& e) {
      logger_.error(name() + ": setup failed: " + e.what());
      return false;
    }
    logger_.debug(name() + ": set up");
  } else if (const auto reason = unavailable_reason()) {
    logger_.warning(name() + ": subscription refused: " + *reason);
    return false;
  }
  ++subscriptions_;
  return true;
}

void Device::unsubscribe() {
  std::lock_guard lock(subscription_mutex_);
  if (subscriptions_ == 0) return;
  if (subscriptions_ == 1) shut_driver_down();
  --subscriptions_;
}

void Device::unsubscribe_from_event_loop() {
  std::lock_guard lock(subscription_mutex_);
  if (subscriptions_ != 1 || !driver_->setup_may_block()) {
    if (subscriptions_ == 1) shut_driver_down();
    if (subscriptions_ > 0) --subscriptions_;
    return;
  }
  // Counted gone first: the server sees the device down (no update(), a
  // newcomer sets it up again, and that subscribe() waits for this thread).
  subscriptions_ = 0;
  // The thread takes no lock: whatever would touch the driver next (a
  // subscribe(), force_shutdown()) joins it first, holding the lock.
  finish_background_shutdown();
  background_shutdown_ = std::thread([this] { shut_driver_down(); });
}

int Device::subscriptions() const { return subscriptions_.load(); }

void Device::force_shutdown() {
  std::lock_guard lock(subscription_mutex_);
  finish_background_shutdown();
  if (subscriptions_ == 0) return;
  subscriptions_ = 0;
  shut_driver_down();
}

void Device::shut_driver_down() {
  try {
    driver_->shutdown();
  } catch (const std::exception& e) {
    // 1.5 kept the device subscribed when Shutdown failed; nobody is left to
    // use it, so count it closed and say so.
    logger_.error(name() + ": shutdown failed: " + e.what());
  }
  logger_.debug(name() + ": shut down");
}

void Device::finish_background_shutdown() {
  if (background_shutdown_.joinable()) background_shutdown_.join();
}

void Device::set_available(bool available, std::string reason) {
  std::lock_guard lock(availability_mutex_);
  available_ = available;
  unavailable_reason_ = available ? std::string() : std::move(reason);
  if (!available_ && unavailable_reason_.empty()) unavailable_reason_ = "the device is unavailable";
}

bool Device::available() const {
  std::lock_guard lock(availability_mutex_);
  return available_;
}

std::optional<std::string> Device::unavailable_reason() const {
  std::lock_guard lock(availability_mutex_);
  if (available_) return std::nullopt;
  return unavailable_reason_;
}

void Device::check() { driver_->check(); }

void Device::prepare() { driver_->prepare(); }

void Device::update() {
  if (driver_->runs_own_thread()) return;
  try {
    driver_->update();
  } catch (const std::exception& e) {
    logger_.error(name() + ": update failed: " + e.what());
  }
  service_requests();
}

void Device::publish(std::vector<std::uint8_t> payload, Timestamp timestamp) {
  {
    std::lock_guard lock(mutex_);
    auto sample = std::make_shared<DataSample>();
    sample->payload = std::move(payload);
    sample->timestamp = timestamp;
    sample->sequence = data_->sequence + 1;
    data_ = std::move(sample);
    if (queues_data()) {
      history_.push_back(data_);
      if (history_.size() > info_.limits.data_queue) history_.pop_front();
    }
  }
  notify_listeners(&DeviceListener::data_published);
}

std::shared_ptr<const DataSample> Device::latest_data() const {
  std::lock_guard lock(mutex_);
  return data_;
}

std::vector<std::shared_ptr<const DataSample>> Device::data_since(std::uint64_t sequence) const {
  std::lock_guard lock(mutex_);
  std::vector<std::shared_ptr<const DataSample>> samples;
  for (const auto& sample : history_) {
    if (sample->sequence > sequence) samples.push_back(sample);
  }
  return samples;
}

Device::CommandStatus Device::put_command(ClientId client, std::span<const std::uint8_t> payload) {
  if (!writable() || command_max_size_ == 0) return CommandStatus::kReadOnly;
  if (payload.size() < command_min_size_ || payload.size() > command_max_size_) {
    return CommandStatus::kWrongSize;
  }
  std::shared_ptr<Wakeup> wakeup;
  {
    std::lock_guard lock(mutex_);
    command_ = Command{{payload.begin(), payload.end()}, clock_.now(), client};
    command_taken_ = false;
    if (info_.limits.command_queue > 0) {
      if (command_queue_.size() == info_.limits.command_queue) command_queue_.pop_front();
      command_queue_.push_back(*command_);
    }
    wakeup = wakeup_;
  }
  if (wakeup) wakeup->notify();
  return CommandStatus::kAccepted;
}

std::optional<Command> Device::take_command() {
  std::lock_guard lock(mutex_);
  if (info_.limits.command_queue > 0) {
    if (command_queue_.empty()) return std::nullopt;
    Command oldest = std::move(command_queue_.front());
    command_queue_.pop_front();
    return oldest;
  }
  if (command_taken_ || !command_) return std::nullopt;
  command_taken_ = true;
  return command_;
}

std::optional<Command> Device::latest_command() const {
  std::lock_guard lock(mutex_);
  return command_;
}

Device::RequestStatus Device::enqueue_request(Request request) {
  std::shared_ptr<Wakeup> wakeup;
  {
    std::lock_guard lock(mutex_);
    if (requests_.size() >= info_.limits.request_queue) return RequestStatus::kQueueFull;
    requests_.push_back(std::move(request));
    wakeup = wakeup_;
  }
  if (wakeup) wakeup->notify();
  return RequestStatus::kQueued;
}

void Device::set_wakeup(std::shared_ptr<Wakeup> wakeup) {
  std::lock_guard lock(mutex_);
  wakeup_ = std::move(wakeup);
}

std::size_t Device::pending_requests() const {
  std::lock_guard lock(mutex_);
  return requests_.size();
}

void Device::service_requests() {
  for (;;) {
    Request request;
    {
      std::lock_guard lock(mutex_);
      if (requests_.empty()) return;
      request = std::move(requests_.front());
      requests_.pop_front();
    }
    RequestResult result;
    try {
      result = driver_->handle_request(request);
    } catch (const std::exception& e) {
      logger_.warning(name() + ": request " + std::to_string(request.subtype()) +
                      " failed: " + e.what());
      result = RequestResult::nack();
    }
    post_reply(Reply{request.client, request.device, result.type, std::move(result.payload),
                     clock_.now()});
  }
}

void Device::post_reply(Reply reply) {
  if (reply.client >= kFirstDriverClient) {
    {
      std::lock_guard lock(mutex_);
      // One that gave up waiting is not waiting any more: its late reply goes.
      if (std::find(awaited_.begin(), awaited_.end(), reply.client) == awaited_.end()) return;
      driver_replies_.push_back(std::move(reply));
    }
    driver_reply_arrived_.notify_all();
    return;
  }
  {
    std::lock_guard lock(mutex_);
    replies_.push_back(std::move(reply));
  }
  notify_listeners(&DeviceListener::replies_ready);
}

std::vector<Reply> Device::take_replies() {
  std::lock_guard lock(mutex_);
  return std::exchange(replies_, {});
}

void Device::expect_reply(ClientId client) {
  std::lock_guard lock(mutex_);
  awaited_.push_back(client);
}

std::optional<Reply> Device::await_reply(ClientId client, std::chrono::steady_clock::time_point deadline) {
  std::unique_lock lock(mutex_);
  std::optional<Reply> found;
  driver_reply_arrived_.wait_until(lock, deadline, [&] {
    const auto it = std::find_if(driver_replies_.begin(), driver_replies_.end(),
                                 [client](const Reply& reply) { return reply.client == client; });
    if (it == driver_replies_.end()) return false;
    found = std::move(*it);
    driver_replies_.erase(it);
    return true;
  });
  return found;
}

void Device::forget_reply(ClientId client) {
  std::lock_guard lock(mutex_);
  std::erase(awaited_, client);
  std::erase_if(driver_replies_, [client](const Reply& reply) { return reply.client == client; });
}

void Device::add_listener(DeviceListener* listener) {
  std::lock_guard lock(listeners_mutex_);
  listeners_.push_back(listener);
}

void Device::remove_listener(DeviceListener* listener) {
  std::unique_lock lock(listeners_mutex_);
  std::erase(listeners_, listener);
  // A notification may be under way with a copy of the list: once this returns
  // the listener may be destroyed, so wait for calls on other threads to end.
  // (A listener removing itself from inside its own callback must not wait on itself.)
  const auto self = std::this_thread::get_id();
  notifications_done_.wait(lock, [&] {
    return std::ranges::all_of(notifying_threads_, [&](std::thread::id id) { return id == self; });
  });
}

void Device::notify_listeners(void (DeviceListener::*event)(const Device&)) {
  std::vector<DeviceListener*> listeners;
  {
    std::lock_guard lock(listeners_mutex_);
    if (listeners_.empty()) return;
    listeners = listeners_;
    notifying_threads_.push_back(std::this_thread::get_id());
  }
  for (DeviceListener* listener : listeners) (listener->*event)(*this);
  {
    std::lock_guard lock(listeners_mutex_);
    notifying_threads_.erase(std::ranges::find(notifying_threads_, std::this_thread::get_id()));
  }
  notifications_done_.notify_all();
}

}  // namespace playerkit::core
