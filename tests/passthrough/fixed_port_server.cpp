#include "fixed_port_server.hpp"

#include <stdexcept>

#include "config/config_file.hpp"
#include "core/instantiate.hpp"
#include "protocol/device_address.hpp"
#include "test_server.hpp"

namespace playerkit::testing {

FixedPortServer::FixedPortServer(const std::string& config_text, std::uint16_t port) {
  logger_.set_sink([](core::LogLevel, std::string_view) {});
  register_test_drivers(registry_);
  server::ServerOptions options;
  options.bind_address = "127.0.0.1";
  server_ = std::make_unique<server::Server>(devices_, clock_, logger_, options);
  port_ = server_->listen(port);
  std::string text = config_text;
  for (auto at = text.find("{PORT}"); at != std::string::npos; at = text.find("{PORT}")) {
    text.replace(at, 6, std::to_string(port_));
  }
  const auto config =
      config::ConfigFile::parse(text, "robot.cfg", core::load_options_for(registry_, port_));
  core::instantiate_devices(config, registry_, devices_, clock_, logger_);
  devices_.prepare_all();
  thread_ = std::thread([this] { server_->run(); });
}

FixedPortServer::~FixedPortServer() {
  server_->stop();
  thread_.join();
  devices_.shutdown_all();
}

core::Device& FixedPortServer::device(std::string_view address) {
  const auto parsed = protocol::parse_device_address(address);
  core::Device* found = parsed ? devices_.find(port_, *parsed) : nullptr;
  if (found == nullptr) throw std::invalid_argument("no such device in the robot's config");
  return *found;
}

}  // namespace playerkit::testing
