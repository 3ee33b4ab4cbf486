#pragma once
// Small drivers for the core tests: they count what the framework does to them.

#include <atomic>
#include <string>

#include "core/device.hpp"
#include "core/driver.hpp"

namespace playerkit::core::testing {

struct CallCounts {
  std::atomic<int> setup{0};
  std::atomic<int> shutdown{0};
  std::atomic<int> update{0};
  std::atomic<int> prepare{0};
};

class CountingDriver : public Driver {
 public:
  explicit CountingDriver(CallCounts& counts, bool refuse_setup = false)
      : counts_(counts), refuse_setup_(refuse_setup) {}

  void prepare() override { ++counts_.prepare; }
  void setup() override {
    ++counts_.setup;
    if (refuse_setup_) throw DriverError("no hardware here");
  }
  void shutdown() override { ++counts_.shutdown; }
  void update() override { ++counts_.update; }
  // Subtype 1 is answered with the request echoed back; everything else NACK.
  RequestResult handle_request(const Request& request) override {
    if (request.subtype() == 1) return RequestResult::ack(request.payload);
    if (request.subtype() == 2) throw std::runtime_error("broken request handler");
    return Driver::handle_request(request);
  }

 private:
  CallCounts& counts_;
  bool refuse_setup_;
};

}  // namespace playerkit::core::testing
