#include "test_server.hpp"

#include <chrono>

#include "config/config_file.hpp"
#include "core/instantiate.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::testing {

namespace {

std::vector<std::uint16_t> every_interface() {
  std::vector<std::uint16_t> codes;
  for (const auto& info : protocol::all_interfaces()) codes.push_back(info.code);
  return codes;
}

class SourceDriver : public core::Driver {};

class ActuatorDriver : public core::Driver {};

class EchoDriver : public core::Driver {
 public:
  core::RequestResult handle_request(const core::Request& request) override {
    if (request.subtype() == 1) return core::RequestResult::ack(request.payload);
    return core::RequestResult::nack();
  }
};

class RefusingDriver : public core::Driver {
 public:
  void setup() override { throw core::DriverError("the test says no"); }
};

class SlowReplyDriver : public core::ThreadedDriver {
 protected:
  void run(std::stop_token stop) override {
    while (!stop.stop_requested()) {
      if (device().pending_requests() > 0) {
        if (!sleep_for(stop, std::chrono::milliseconds(200))) return;
        device().service_requests();
      }
      if (!sleep_for(stop, std::chrono::milliseconds(5))) return;
    }
  }
  core::RequestResult handle_request(const core::Request& request) override {
    return core::RequestResult::ack(request.payload);
  }
};

template <typename T>
core::DriverFactory make() {
  return [](const core::DriverContext&) { return std::make_unique<T>(); };
}

}  // namespace

void register_test_drivers(core::DriverRegistry& registry) {
  using protocol::Access;
  registry.add({"source", every_interface(), Access::kRead, make<SourceDriver>(), {}, "test data"});
  registry.add({"actuator", {protocol::kPositionCode}, Access::kAll, make<ActuatorDriver>(), {}, ""});
  registry.add({"echo", every_interface(), Access::kAll, make<EchoDriver>(), {}, ""});
  registry.add({"refuser", every_interface(), Access::kAll, make<RefusingDriver>(), {}, ""});
  registry.add({"slowreply", every_interface(), Access::kAll, make<SlowReplyDriver>(),
                core::DeviceLimits{1}, ""});
}

TestServer::TestServer(const std::string& config_text, server::ServerOptions options,
                       int extra_ports,
                       const std::function<void(core::DriverRegistry&)>& add_drivers) {
  logger_.set_level(core::LogLevel::kDebug);
  logger_.set_sink([this](core::LogLevel level, std::string_view line) {
    std::lock_guard lock(log_mutex_);
    log_.push_back(std::string(core::to_string(level)) + ": " + std::string(line));
  });
  register_test_drivers(registry_);
  if (add_drivers) add_drivers(registry_);
  options.bind_address = "127.0.0.1";
  server_ = std::make_unique<server::Server>(devices_, clock_, logger_, options);
  for (int i = 0; i <= extra_ports; ++i) ports_.push_back(server_->listen(0));

  std::string text = config_text;
  for (std::size_t i = 0; i < ports_.size(); ++i) {
    const std::string name = i == 0 ? "{PORT}" : "{PORT" + std::to_string(i + 1) + "}";
    for (auto at = text.find(name); at != std::string::npos; at = text.find(name)) {
      text.replace(at, name.size(), std::to_string(ports_[i]));
    }
  }
  const auto config = config::ConfigFile::parse(text, "test.cfg",
                                                core::load_options_for(registry_, ports_[0]));
  core::instantiate_devices(config, registry_, devices_, clock_, logger_);
  devices_.prepare_all();
  devices_.start_alwayson();
  thread_ = std::thread([this] { server_->run(); });
}

TestServer::~TestServer() { stop(); }

void TestServer::stop() {
  if (stopped_) return;
  stopped_ = true;
  server_->stop();
  thread_.join();
  devices_.shutdown_all();
}

core::Device& TestServer::device(std::string_view address, std::size_t port_index) {
  const auto parsed = protocol::parse_device_address(address);
  if (!parsed) throw std::invalid_argument("bad device address");
  core::Device* found = devices_.find(ports_.at(port_index), *parsed);
  if (found == nullptr) throw std::invalid_argument("no such device in the test config");
  return *found;
}

std::vector<std::string> TestServer::log_lines() const {
  std::lock_guard lock(log_mutex_);
  return log_;
}

bool TestServer::logged(std::string_view text) const {
  std::lock_guard lock(log_mutex_);
  for (const auto& line : log_) {
    if (line.find(text) != std::string::npos) return true;
  }
  return false;
}

}  // namespace playerkit::testing
