// The flockofbirds driver: a Flock of Birds as a position3d device. The
// kit's SerialDeviceDriver opens the port, wakes this driver when records
// arrive, a command or request comes or the stream is overdue, and looks for
// the bird again when it goes quiet; what is here is the bird's start-up
// (BirdLink) and the mapping of its records to position3d (flockofbirds.md §3).
#include "families/flockofbirds/driver/flockofbirds_driver.hpp"

#include <atomic>
#include <memory>
#include <string>

#include "families/flockofbirds/driver/bird_link.hpp"
#include "families/flockofbirds/driver/flockofbirds_options.hpp"
#include "families/flockofbirds/driver/position3d_mapping.hpp"
#include "hardware_driver/serial_device_driver.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

using namespace std::chrono_literals;
namespace fob = hardware::flockofbirds;

// A streaming bird sends 20 to 144 records a second; half a second without
// one means it is gone.
constexpr auto kStreamTimeout = 500ms;

class FlockOfBirdsDriver final : public hardware_driver::SerialDeviceDriver {
 public:
  explicit FlockOfBirdsDriver(const flockofbirds::FlockSettings& settings)
      : SerialDeviceDriver(settings.port, {.baud = settings.baud}, {}), baud_(settings.baud) {}

 private:
  void start_device(links::ByteLink& link, bool /*recovering*/) override {
    bird_ = std::make_unique<flockofbirds::BirdLink>(link, [this] { return stopping(); });
    try {
      scaling_ = bird_->start();
    } catch (const links::ExchangeError& e) {
      if (e.kind() == links::ExchangeError::Kind::stopped) throw hardware_driver::Stopping();
      throw std::runtime_error(std::string(e.what()) + " (is it powered and in stand-alone mode, and does baudrate " +
                               std::to_string(baud_) + " match its switches?)");
    }
    last_record_ = Clock::now();
  }

  void serve(links::ByteLink& /*link*/, const core::Wakeup::Woken& woke) override {
    if (woke.readable) {
      const auto arrived = bird_->arrivals();
      ++looks_;
      records_ += arrived.count;
      if (arrived.newest) {
        last_record_ = Clock::now();
        const fob::BirdPose pose = fob::pose_from_words(*arrived.newest, scaling_);
        device().publish(protocol::encode(flockofbirds::position3d_from_bird(pose)));
      }
    }
    // A tracker has nothing to command; 1.5 read commands and ignored them.
    while (device().take_command()) {
    }
    device().service_requests();  // every request NACKed, as 1.5 did
    if (Clock::now() - last_record_ > kStreamTimeout) {
      throw hardware_driver::DeviceLost("no record for " + std::to_string(kStreamTimeout.count()) + " ms");
    }
  }

  [[nodiscard]] Clock::time_point next_deadline() const override { return last_record_ + kStreamTimeout + 1ms; }

  void stop_device(links::ByteLink& /*link*/) noexcept override {
    // Point mode, as 1.5 left it: the next opener finds a quiet line.
    try {
      if (bird_) bird_->stop();
    } catch (const std::exception& e) {
      device().logger().warning(device().name() + ": could not stop the bird's stream: " + e.what());
    }
  }

  void link_closing() noexcept override { bird_.reset(); }
  [[nodiscard]] std::string subject() const override { return "the Flock of Birds on " + port(); }
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override {
    return {{"records", records_.load()}};
  }
  [[nodiscard]] std::uint64_t own_timeouts() const override { return looks_.load(); }

  const int baud_;
  std::unique_ptr<flockofbirds::BirdLink> bird_;
  fob::PositionScaling scaling_ = fob::PositionScaling::inches_36;
  Clock::time_point last_record_{};
  std::atomic<std::uint64_t> records_{0};
  std::atomic<std::uint64_t> looks_{0};  // reads of what had arrived: not timeouts
};

}  // namespace

core::DriverSpec flockofbirds_driver_spec() {
  return {
      .name = "flockofbirds",
      .interfaces = {protocol::kPosition3dCode},
      .access = protocol::Access::kAll,
      .factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
        return std::make_unique<FlockOfBirdsDriver>(flockofbirds::read_flockofbirds_settings(context.section));
      },
      .limits = {},
      .summary = "Ascension Flock of Birds 6-DOF tracker (position3d)",
      .family = "flockofbirds",
      .doc = {.manual_section = "7.10",
              .needs_hardware = true,
              .options = {},
              .requests = {"none: every request is NACKed, as in 1.5 (commands are accepted and ignored)"},
              .example = "position3d:0 ( driver \"flockofbirds\" port \"/dev/ttyS0\" )",
              .schema = flockofbirds::flockofbirds_option_schema()},
  };
}

}  // namespace playerkit::drivers
