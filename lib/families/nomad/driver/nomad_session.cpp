#include "families/nomad/driver/nomad_session.hpp"

#include <stdexcept>
#include <string>

namespace playerkit::drivers::nomad {

namespace nomad = hardware::nomad;

namespace {

// The longest reply worth waiting for: a state with some room to spare (the
// sensor mask asks for no laser points). A reply that stalls half way is
// waited for as long as this takes on a slow line, so it stays short.
constexpr std::size_t kLongestReply = nomad::kHeaderSize + 4 * (nomad::kStateWords + 64);

}  // namespace

NomadSession::NomadSession(links::ByteLink& link, std::function<bool()> stopping, SessionTimeouts timeouts)
    : reader_(link, format_, kLongestReply),
      exchanger_(reader_, std::move(stopping), "the Nomad server"),
      timeouts_(timeouts) {}

nomad::Message NomadSession::ask(const nomad::Message& request, std::chrono::milliseconds timeout) {
  const auto telegram = exchanger_.exchange(
      {.name = std::string(nomad::type_name(request.type)),
       .bytes = nomad::encode(request),
       .matcher =
           [](std::span<const std::uint8_t> reply) {
             const auto message = nomad::decode(reply);
             if (message && nomad::is_failure(*message)) return links::ReplyMatch::refusal;
             return links::ReplyMatch::mine;  // lock-step: the next message answers
           },
       .timeout = timeout,
       // A reply cut short never ends: what came of it is dropped and the
       // request sent again (each is idempotent) before the robot is lost.
       .attempts = 2,
       .flush_first = true});
  auto message = nomad::decode(telegram);
  if (!message) throw std::runtime_error("the Nomad server's reply to " + std::string(nomad::type_name(request.type)) +
                                         " does not match its length");
  return *message;
}

void NomadSession::start(std::int32_t client_pid, bool zero) {
  // The server may answer CONNECT_ROBOT with any type (nomad.md §1.2);
  // after it, only states and errors.
  format_.expect({});
  const nomad::Message connected = ask(nomad::connect_robot(client_pid), timeouts_.reply);
  format_.expect(nomad::state_reply_types());
  if (connected.words.empty() || connected.words[0] == 0) {
    throw std::runtime_error("the Nomad server refused CONNECT_ROBOT for robot " + std::to_string(nomad::kRobotId) +
                             " (it answered port 0)");
  }
  ask(nomad::sensor_mask(), timeouts_.reply);
  ask(nomad::command_timeout(nomad::kCommandTimeoutSeconds), timeouts_.reply);
  if (zero) ask(nomad::zero(), timeouts_.zero);
  ask(nomad::accelerations(nomad::kSetupAccelerations), timeouts_.reply);
  ask(nomad::speeds(nomad::kSetupSpeeds), timeouts_.reply);
}

void NomadSession::send_velocity(std::int32_t translation, std::int32_t steering, std::int32_t turret) {
  ask(nomad::velocity(translation, steering, turret), timeouts_.reply);
}

nomad::RobotState NomadSession::read_state() {
  const nomad::Message reply = ask(nomad::get_state(), timeouts_.reply);
  auto state = nomad::parse_state(reply);
  if (!state) {
    throw std::runtime_error("the Nomad server answered GS with " + std::string(nomad::type_name(reply.type)) + " of " +
                             std::to_string(reply.words.size()) + " words, not a state");
  }
  return *state;
}

void NomadSession::stop_motion() { ask(nomad::velocity(0, 0, 0), timeouts_.reply); }

}  // namespace playerkit::drivers::nomad
