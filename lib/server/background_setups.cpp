#include "server/background_setups.hpp"

#include <utility>

#include <boost/asio/post.hpp>

namespace playerkit::server {

BackgroundSetups::~BackgroundSetups() { wait_all(); }

void BackgroundSetups::start(core::Device& device, std::function<void(bool)> done) {
  const unsigned long id = next_id_++;
  threads_.emplace(id, std::thread([this, id, &device, done = std::move(done)]() mutable {
    const bool subscribed = device.subscribe();  // setup() here, when it is the first
    boost::asio::post(io_, [this, id, subscribed, done = std::move(done)] {
      if (const auto it = threads_.find(id); it != threads_.end()) {
        it->second.join();
        threads_.erase(it);
      }
      done(subscribed);
    });
  }));
}

void BackgroundSetups::wait_all() {
  for (auto& [id, thread] : threads_) thread.join();
  threads_.clear();
}

}  // namespace playerkit::server
