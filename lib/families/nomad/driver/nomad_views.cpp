// nomad_position and nomad_sonar: a nomad device's data in the position and
// sonar interfaces, as 1.5 built them (nomad.md §2.2, §2.3): each subscribes
// to nomad:`nomad_index` and republishes what it publishes; the position
// device's commands go to it as nomad commands. No link of their own.
#include <memory>

#include "core/device.hpp"
#include "core/device_table.hpp"
#include "core/source_subscription.hpp"
#include "families/nomad/driver/nomad_drivers.hpp"
#include "families/nomad/driver/nomad_mapping.hpp"
#include "families/nomad/driver/nomad_options.hpp"
#include "interfaces/position_requests.hpp"
#include "interfaces/ranger_requests.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {

namespace {

// The commands a view forwards carry this client id on the nomad device.
constexpr core::ClientId kViewClient = core::kFirstDriverClient + 0x4E4F;

class NomadView : public core::Driver, private core::DeviceListener {
 public:
  NomadView(nomad::NomadSourceSettings settings, core::DeviceTable& devices)
      : settings_(settings), devices_(devices) {}
  ~NomadView() override { source_.reset(); }

  void check() override { (void)nomad_device(); }
  [[nodiscard]] std::vector<core::DeviceKey> source_devices() const override { return {source_key()}; }
  void setup() override { source_ = core::SourceSubscription(nomad_device(), this, device().name()); }
  void shutdown() override { source_.reset(); }

 protected:
  virtual void republish(const protocol::NomadData& data) = 0;
  [[nodiscard]] core::Device* source() const { return source_.device(); }

 private:
  [[nodiscard]] core::DeviceKey source_key() const {
    const std::uint16_t port = settings_.nomad_port == 0 ? device().key().port
                                                         : static_cast<std::uint16_t>(settings_.nomad_port);
    return {port, {protocol::kNomadCode, static_cast<std::uint16_t>(settings_.nomad_index)}};
  }

  core::Device& nomad_device() const {
    if (settings_.nomad_port == 0) {
      return core::source_device(devices_, device(), protocol::kNomadCode, settings_.nomad_index, "nomad_index",
                                 "repackage");
    }
    core::Device* found = devices_.find(source_key());
    if (found == nullptr) {
      throw core::DriverError(device().name() + ": no nomad:" + std::to_string(settings_.nomad_index) + " on port " +
                              std::to_string(settings_.nomad_port) + " (nomad_port) to repackage");
    }
    return *found;
  }

  // On the nomad device's thread.
  void data_published(const core::Device& nomad) override {
    const auto sample = nomad.latest_data();
    if (!sample || sample->payload.size() != protocol::NomadData::kWireSize) return;
    republish(protocol::decode<protocol::NomadData>(sample->payload));
  }
  void replies_ready(const core::Device&) override {}

  const nomad::NomadSourceSettings settings_;
  core::DeviceTable& devices_;
  core::SourceSubscription source_;
};

class NomadPositionDriver final : public NomadView, private interfaces::PositionBase {
 public:
  using NomadView::NomadView;

  void update() override {
    auto command = device().take_command();
    if (!command || source() == nullptr) return;
    const auto position = protocol::decode<protocol::PositionCommand>(command->payload);
    (void)source()->put_command(kViewClient, protocol::encode(nomad::nomad_command(position)));
  }

  core::RequestResult handle_request(const core::Request& request) override {
    return interfaces::answer_position_request(*this, request);
  }

 private:
  void republish(const protocol::NomadData& data) override {
    device().publish(protocol::encode(nomad::position_data(data)));
  }
  std::optional<interfaces::BaseGeometry> geometry() override {
    return interfaces::BaseGeometry{{}, nomad::kBodyDiameter, nomad::kBodyDiameter};
  }
};

class NomadSonarDriver final : public NomadView, private interfaces::RangerArray {
 public:
  using NomadView::NomadView;

  core::RequestResult handle_request(const core::Request& request) override {
    return interfaces::answer_sonar_request(*this, request);
  }

 private:
  void republish(const protocol::NomadData& data) override {
    device().publish(protocol::encode(nomad::sonar_data(data)));
  }
  std::optional<std::vector<geometry::Pose2>> sensor_poses() override { return nomad::sonar_poses(); }
};

template <class View>
core::DriverFactory view_factory(std::string driver) {
  return [driver](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
    return std::make_unique<View>(nomad::read_nomad_source_settings(context.section, driver), context.devices);
  };
}

}  // namespace

core::DriverSpec nomad_position_driver_spec() {
  return {
      .name = "nomad_position",
      .interfaces = {protocol::kPositionCode},
      .access = protocol::Access::kAll,
      .factory = view_factory<NomadPositionDriver>("nomad_position"),
      .limits = {},
      .summary = "a nomad device's odometry and velocity control (position)",
      .family = "nomad",
      .doc = {.manual_section = "7.29",
              .needs_hardware = false,
              .options = {},
              .requests = {"GET_GEOM: centred, 800 x 800 mm"},
              .example = "position:0 ( driver \"nomad_position\" nomad_index 0 )",
              .schema = nomad::nomad_source_option_schema()},
  };
}

core::DriverSpec nomad_sonar_driver_spec() {
  return {
      .name = "nomad_sonar",
      .interfaces = {protocol::kSonarCode},
      .access = protocol::Access::kRead,
      .factory = view_factory<NomadSonarDriver>("nomad_sonar"),
      .limits = {},
      .summary = "a nomad device's 16 sonars (sonar)",
      .family = "nomad",
      .doc = {.manual_section = "7.29",
              .needs_hardware = false,
              .options = {},
              .requests = {"GET_GEOM: 16 transducers on a 400 mm ring, 22.5 degrees apart"},
              .example = "sonar:0 ( driver \"nomad_sonar\" nomad_index 0 )",
              .schema = nomad::nomad_source_option_schema()},
  };
}

}  // namespace playerkit::drivers
