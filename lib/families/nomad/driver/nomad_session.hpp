#pragma once
// One conversation with the Nomad server in lock-step (nomad.md §1.3): the
// setup sequence, then a velocity command and a state request per cycle.
// Each request waits for its reply; an ERROR_MSG (or type -1) refuses it.

#include <chrono>
#include <cstdint>
#include <functional>

#include "families/nomad/protocol/nclient_message.hpp"
#include "families/nomad/protocol/nomad_requests.hpp"
#include "links/exchange.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::drivers::nomad {

struct SessionTimeouts {
  std::chrono::milliseconds reply{2000};
  // ZR aligns steering and turret; a real robot takes up to 2 minutes.
  std::chrono::milliseconds zero{130'000};
};

class NomadSession {
 public:
  NomadSession(links::ByteLink& link, std::function<bool()> stopping, SessionTimeouts timeouts = {});

  // CONNECT_ROBOT, CT, CONF_TM 5, ZR (unless `zero` is false), AC, SP.
  // Throws links::ExchangeError or std::runtime_error naming the step.
  void start(std::int32_t client_pid, bool zero);
  // VM: translation in 0.1 in/s, steering and turret in 0.1 deg/s.
  void send_velocity(std::int32_t translation, std::int32_t steering, std::int32_t turret);
  // GS: the robot's state. Throws std::runtime_error for a reply that is no state.
  hardware::nomad::RobotState read_state();
  // VM 0 0 0, for shutdown.
  void stop_motion();

 private:
  hardware::nomad::Message ask(const hardware::nomad::Message& request, std::chrono::milliseconds timeout);

  hardware::nomad::NclientFormat format_;
  links::FramedReader reader_;
  links::Exchanger exchanger_;
  SessionTimeouts timeouts_;
};

}  // namespace playerkit::drivers::nomad
