// The other simulated devices: sonar, fiducial finder, truth, ptz, gripper,
// power, blobfinder and the simulation control, on worlds made here.
#include <gtest/gtest.h>

#include <cmath>

#include "drivers/sim/sim_test_support.hpp"
#include "protocol/messages/blobfinder.hpp"
#include "protocol/messages/fiducial.hpp"
#include "protocol/messages/gripper.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/power.hpp"
#include "protocol/messages/ptz.hpp"
#include "protocol/messages/simulation.hpp"
#include "protocol/messages/sonar.hpp"
#include "protocol/messages/truth.hpp"

namespace playerkit::drivers::sim {
namespace sim_devices_test {

using namespace testing;
using protocol::MessageType;

// One subscribed device of `config` on `world`, stepped once.
struct OneDevice {
  OneDevice(World world, const std::string& config, std::uint16_t served)
      : sim(std::move(world)), interface(served) {
    sim.load(config);
    if (!device().subscribe()) throw std::runtime_error("subscription refused");
  }
  core::Device& device() { return sim.device(interface); }
  template <class T>
  T read(int steps = 1) {
    sim.step(steps);
    sim.cycle(device());
    return sim.latest<T>(device());
  }
  SimDevices sim;
  std::uint16_t interface;
};

TEST(SimSonarTest, RangesAndTransducerPosesInMillimetres) {
  grid::OccupancyGrid map = open_floor();
  add_wall(map, 1.5, -5.0, 2.0, 5.0);  // 1.5 m ahead of the robot's centre
  World world({.step = 0.1, .seed = 1}, std::move(map));
  const ModelId robot = world.add(test_robot("robot"));
  SonarSpec ring;
  ring.transducers = {{0.2, 0.0, 0.0}, {0.0, 0.1, std::numbers::pi / 2}};
  ring.range_max = 5.0;
  world.add(on(robot, "robot.sonar", ring, {0.05, 0.0, 0.0}));
  OneDevice sonar(std::move(world), "sonar:0 ( driver \"sonar\" model \"robot.sonar\" )\n", protocol::kSonarCode);

  const auto data = sonar.read<protocol::SonarData>();
  ASSERT_EQ(data.range_count, 2);
  EXPECT_NEAR(data.ranges[0], 1000 * (1.5 - 0.25), 1000 * kCell);  // from the transducer at x = 0.25
  EXPECT_EQ(data.ranges[1], 5000);                                 // sideways: nothing

  const core::Reply reply = sonar.sim.ask(sonar.device(), {protocol::kSonarGetGeomReq});
  ASSERT_EQ(reply.type, MessageType::kAck);
  const auto geom = protocol::decode<protocol::SonarGeom>(reply.payload);
  ASSERT_EQ(geom.pose_count, 2);
  EXPECT_EQ(geom.poses[0], (std::array<std::int16_t, 3>{250, 0, 0}));
  EXPECT_EQ(geom.poses[1], (std::array<std::int16_t, 3>{50, 100, 90}));
}

TEST(SimFiducialTest, ABeaconAheadIsSeenWithItsIdRangeAndBearing) {
  World world({.step = 0.1, .seed = 1}, open_floor());
  const ModelId robot = world.add(test_robot("robot"));
  FiducialSpec finder;
  finder.range_max = 8.0;
  finder.range_max_id = 5.0;
  world.add(on(robot, "robot.finder", finder));
  ModelSpec near_beacon;
  near_beacon.name = "near";
  near_beacon.pose = {3.0, 3.0, 0.0};  // 45° left, 4.24 m
  near_beacon.body = {.shape = Shape::circle, .size = {0.2, 0.2}};
  near_beacon.returns.fiducial_id = 5;
  world.add(near_beacon);
  ModelSpec far_beacon = near_beacon;
  far_beacon.name = "far";
  far_beacon.pose = {-6.0, 0.0, 0.0};  // behind: out of the 180° view
  world.add(far_beacon);
  ModelSpec unnamed = near_beacon;
  unnamed.name = "unnamed";
  unnamed.pose = {6.0, 0.0, 0.0};  // straight ahead, beyond the id range
  world.add(unnamed);
  OneDevice fiducial(std::move(world), "fiducial:0 ( driver \"lbd\" model \"robot\" )\n", protocol::kFiducialCode);

  const auto data = fiducial.read<protocol::FiducialData>(2);  // 5 Hz
  ASSERT_EQ(data.count, 2);
  EXPECT_EQ(data.fiducials[0].id, 5);
  EXPECT_NEAR(data.fiducials[0].pose[0], 1000 * std::hypot(3.0, 3.0), 1);
  EXPECT_EQ(data.fiducials[0].pose[1], 45);
  EXPECT_EQ(data.fiducials[1].id, -1);  // too far to identify: Player's "unidentified"
  EXPECT_NEAR(data.fiducials[1].pose[0], 6000, 1);
  EXPECT_EQ(data.fiducials[1].pose[1], 0);

  const core::Reply reply = fiducial.sim.ask(fiducial.device(), {protocol::kFiducialGetFov});
  ASSERT_EQ(reply.type, MessageType::kAck);
  const auto fov = protocol::decode<protocol::FiducialFov>(reply.payload);
  EXPECT_EQ(fov.max_range, 8000);
  EXPECT_EQ(fov.view_angle, 180);
}

World truth_world() {
  World world({.step = 0.1, .seed = 1}, open_floor());
  ModelSpec robot = test_robot("robot", {0.5, -0.5, 0.0});
  robot.returns.fiducial_id = 7;
  const ModelId id = world.add(robot);
  world.add(on(id, "robot.truth", TruthSpec{}));
  return world;
}

TEST(SimTruthTest, SetPoseTeleportsTheRobotAndPositionFollows) {
  SimDevices sim{truth_world()};
  sim.load("truth:0 ( driver \"truth\" model \"robot.truth\" )\n"
           "position:0 ( driver \"position\" model \"robot\" )\n");
  core::Device& truth = sim.device(protocol::kTruthCode);
  core::Device& position = sim.device(protocol::kPositionCode);
  ASSERT_TRUE(truth.subscribe());
  ASSERT_TRUE(position.subscribe());

  sim.step();
  sim.cycle(truth);
  auto data = sim.latest<protocol::TruthData>(truth);
  EXPECT_EQ(data.px, 500);
  EXPECT_EQ(data.py, -500);

  protocol::TruthPose set;
  set.subtype = protocol::kTruthSetPose;
  set.px = 1000;
  set.py = 2000;
  set.pa = 90;
  EXPECT_EQ(sim.ask(truth, protocol::encode(set)).type, MessageType::kAck);
  const core::Reply reply = sim.ask(truth, {protocol::kTruthGetPose});
  ASSERT_EQ(reply.type, MessageType::kAck);
  const auto pose = protocol::decode<protocol::TruthPose>(reply.payload);
  EXPECT_EQ(pose.px, 1000);
  EXPECT_EQ(pose.py, 2000);
  EXPECT_EQ(pose.pa, 90);

  sim.step();
  sim.cycle(truth);
  sim.cycle(position);
  data = sim.latest<protocol::TruthData>(truth);
  EXPECT_EQ(data.px, 1000);
  EXPECT_EQ(data.pa, 90);
  const auto odometry = sim.latest<protocol::PositionData>(position);  // gps: the true pose
  EXPECT_EQ(odometry.xpos, 1000);
  EXPECT_EQ(odometry.ypos, 2000);
  EXPECT_EQ(odometry.yaw, 90);

  const auto id = protocol::decode<protocol::TruthFiducialId>(sim.ask(truth, {protocol::kTruthGetFiducialId}).payload);
  EXPECT_EQ(id.id, 7);
}

TEST(SimTruthTest, WatchingTheTruthDoesNotSetTheRobotGoing) {
  SimDevices sim{truth_world()};
  sim.load("truth:0 ( driver \"gz_truth\" gz_id \"robot\" )\n");
  core::Device& truth = sim.device(protocol::kTruthCode);
  ASSERT_TRUE(truth.subscribe());
  const ModelId robot = sim.host().with_world([](World& world) { return *world.find("robot"); });
  EXPECT_FALSE(sim.host().with_world([&](World& world) { return world.active(robot); }));
  sim.step();
  sim.cycle(truth);
  EXPECT_EQ(sim.latest<protocol::TruthData>(truth).px, 500);
}

TEST(SimPtzTest, PanAndZoomCommandsAreReportedInDegrees) {
  World world({.step = 0.1, .seed = 1}, open_floor());
  const ModelId robot = world.add(test_robot("robot"));
  PtzSpec head;
  head.max_fov = std::numbers::pi / 3;
  head.min_fov = std::numbers::pi / 36;
  world.add(on(robot, "robot.ptz", head));
  OneDevice ptz(std::move(world), "ptz:0 ( driver \"ptz\" model \"robot.ptz\" )\n", protocol::kPtzCode);
  protocol::PtzCommand command;
  command.pan = 30;
  command.zoom = 40;
  ASSERT_EQ(ptz.device().put_command(1, protocol::encode(command)), core::Device::CommandStatus::kAccepted);
  ptz.sim.cycle(ptz.device());
  auto data = ptz.read<protocol::PtzData>();
  EXPECT_EQ(data.pan, 30);
  EXPECT_EQ(data.tilt, 0);
  EXPECT_EQ(data.zoom, 40);
  command.pan = 150;  // past the head's 100°
  command.zoom = 1;   // below its fov / 12
  ASSERT_EQ(ptz.device().put_command(1, protocol::encode(command)), core::Device::CommandStatus::kAccepted);
  ptz.sim.cycle(ptz.device());
  data = ptz.read<protocol::PtzData>();
  EXPECT_EQ(data.pan, 100);
  EXPECT_EQ(data.zoom, 5);
}

TEST(SimGripperTest, CloseTakesThePuckBetweenThePaddlesAndOpenPutsItDown) {
  World world({.step = 0.1, .seed = 1}, open_floor());
  const ModelId robot = world.add(test_robot("robot"));
  ModelSpec gripper = on(robot, "robot.gripper", GripperSpec{}, {0.3, 0.0, 0.0});
  gripper.body = {.shape = Shape::rectangle, .size = {0.1, 0.3}};
  world.add(gripper);
  ModelSpec puck;
  puck.name = "puck";
  puck.pose = {0.4, 0.0, 0.0};  // between the paddles (front edge at 0.35, reach 0.1)
  puck.body = {.shape = Shape::circle, .size = {0.08, 0.08}};
  puck.returns.obstacle = false;
  puck.returns.gripper = true;
  world.add(puck);
  OneDevice grip(std::move(world), "gripper:0 ( driver \"gz_gripper\" gz_id \"robot\" )\n", protocol::kGripperCode);

  auto data = grip.read<protocol::GripperData>();
  EXPECT_EQ(data.state, 0x01);               // open
  EXPECT_EQ(data.beams, 0x10 | 0x20 | 0x08);  // paddles open, inner beam broken
  protocol::GripperCommand close;
  close.cmd = 2;  // GRIPclose
  ASSERT_EQ(grip.device().put_command(1, protocol::encode(close)), core::Device::CommandStatus::kAccepted);
  grip.sim.cycle(grip.device());
  data = grip.read<protocol::GripperData>();
  EXPECT_EQ(data.state, 0x02);  // closed, holding it
  EXPECT_EQ(data.beams & 0x08, 0x08);
  protocol::GripperCommand open;
  open.cmd = 1;  // GRIPopen
  ASSERT_EQ(grip.device().put_command(1, protocol::encode(open)), core::Device::CommandStatus::kAccepted);
  grip.sim.cycle(grip.device());
  EXPECT_EQ(grip.read<protocol::GripperData>().state, 0x01);
}

TEST(SimPowerTest, TheVoltageIsInDecivolts) {
  World world({.step = 0.1, .seed = 1}, open_floor());
  const ModelId robot = world.add(test_robot("robot"));
  PowerSpec battery;
  battery.full_volts = 13.0;
  battery.interval = 0.1;
  world.add(on(robot, "robot.power", battery));
  OneDevice power(std::move(world), "power:0 ( driver \"power\" model \"robot\" )\n", protocol::kPowerCode);
  const auto data = power.read<protocol::PowerData>();
  EXPECT_NEAR(data.charge, 130, 1);  // nearly full: 13 V
  const core::Reply reply = power.sim.ask(power.device(), {protocol::kMainPowerReq});
  ASSERT_EQ(reply.type, MessageType::kAck);
  EXPECT_EQ(protocol::decode<protocol::PowerData>(reply.payload).charge, data.charge);
}

TEST(SimBlobfinderTest, AColouredBoxAheadIsOneBlobOfItsChannel) {
  World world({.step = 0.1, .seed = 1}, open_floor());
  const ModelId robot = world.add(test_robot("robot"));
  BlobfinderSpec camera;
  camera.channels = {Rgb{255, 0, 0}, Rgb{0, 255, 0}};
  world.add(on(robot, "robot.camera", camera));
  ModelSpec box;
  box.name = "box";
  box.pose = {3.0, 0.0, 0.0};
  box.body.size = {0.5, 0.5};
  box.color = Rgb{0, 255, 0};
  world.add(box);
  OneDevice blobs(std::move(world), "blobfinder:0 ( driver \"vision\" model \"robot.camera\" )\n",
                  protocol::kBlobfinderCode);
  const auto data = blobs.read<protocol::BlobfinderData>();
  EXPECT_EQ(data.width, 80);
  EXPECT_EQ(data.height, 60);
  EXPECT_EQ(data.header[0].num, 0);
  ASSERT_EQ(data.header[1].num, 1);
  ASSERT_EQ(data.blobs.size(), 1u);
  EXPECT_EQ(data.blobs[0].color, 0x00FF00u);
  EXPECT_NEAR(data.blobs[0].x, 40, 2);  // centred
  EXPECT_NEAR(data.blobs[0].range, 2750, 1000 * kCell);  // to the box's near face
}

TEST(SimControlTest, PauseRunAndStepCommands) {
  World world({.step = 0.1, .seed = 1}, open_floor());
  world.add(test_robot("robot"));
  SimDevices sim{std::move(world), {.speedup = 0.0, .run_limit = std::nullopt, .start_paused = true}};
  sim.load("simulation:0 ( driver \"simulation\" )\n");
  core::Device& control = sim.device(protocol::kSimulationCode);
  ASSERT_TRUE(control.subscribe());
  sim.cycle(control);
  EXPECT_EQ(sim.latest<protocol::SimulationData>(control).data, 1);  // paused
  const auto send = [&](std::uint8_t command) {
    ASSERT_EQ(control.put_command(1, std::vector<std::uint8_t>{command}), core::Device::CommandStatus::kAccepted);
    sim.cycle(control);
  };
  send(2);  // one step
  EXPECT_EQ(sim.host().time(), 0.1);
  EXPECT_EQ(control.latest_data()->timestamp, (protocol::Timestamp{0, 100000}));
  send(0);  // run, as fast as it goes
  ASSERT_TRUE(drivers::testing::eventually([&] { return sim.host().time() > 1.0; }));
  send(1);
  EXPECT_TRUE(sim.host().paused());
  EXPECT_EQ(sim.latest<protocol::SimulationData>(control).data, 1);
}

TEST(SimControlTest, RequestsActBeforeTheirAck) {
  World world({.step = 0.1, .seed = 1}, open_floor());
  world.add(test_robot("robot"));
  SimDevices sim{std::move(world), {.speedup = 0.0, .run_limit = std::nullopt, .start_paused = false}};
  sim.load("simulation:0 ( driver \"simulation\" )\n");
  core::Device& control = sim.device(protocol::kSimulationCode);
  ASSERT_TRUE(control.subscribe());  // the world runs flat out
  core::Reply reply = sim.ask(control, {1});
  ASSERT_EQ(reply.type, MessageType::kAck);
  EXPECT_EQ(protocol::decode<protocol::SimulationData>(reply.payload).data, 1);
  const auto steps = sim.host().with_world([](World& w) { return w.steps(); });
  reply = sim.ask(control, {2});
  ASSERT_EQ(reply.type, MessageType::kAck);
  EXPECT_EQ(sim.host().with_world([](World& w) { return w.steps(); }), steps + 1);
  EXPECT_EQ(sim.ask(control, {7}).type, MessageType::kNack);
  reply = sim.ask(control, {0});
  EXPECT_EQ(protocol::decode<protocol::SimulationData>(reply.payload).data, 0);
}

}  // namespace sim_devices_test
}  // namespace playerkit::drivers::sim
