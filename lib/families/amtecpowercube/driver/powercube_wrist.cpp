#include "families/amtecpowercube/driver/powercube_wrist.hpp"

#include <algorithm>
#include <stdexcept>

#include "families/amtecpowercube/protocol/powercube_units.hpp"
#include <string>

namespace playerkit::drivers::amtecpowercube {

const char* module_name(pc::Module module) {
  return module == pc::Module::pan ? "pan module 12" : "tilt module 11";
}

PowercubeWrist::PowercubeWrist(links::ByteLink& link, std::function<bool()> stopping)
    : format_(pc::frame_options()),
      reader_(link, format_, pc::kLongestFrame),
      exchanger_(reader_, std::move(stopping), "the PowerCube wrist") {}

pc::Frame PowercubeWrist::ask(pc::Module module, const std::vector<std::uint8_t>& data) {
  pc::Frame reply;
  const bool is_get = data[0] == static_cast<std::uint8_t>(pc::CommandCode::get_extended);
  exchanger_.exchange(
      {.name = std::string(module_name(module)) + " command " + std::to_string(data[0]),
       .bytes = pc::encode(module, data),
       .matcher =
           [&](std::span<const std::uint8_t> telegram) {
             auto frame = pc::decode(telegram);
             // Another module's reply, or one to an earlier command, is not this one.
             if (!frame || frame->module != static_cast<std::uint8_t>(module) || frame->data.empty() ||
                 frame->data[0] != data[0] || (is_get && !pc::reply_value(*frame, static_cast<pc::Parameter>(data[1])))) {
               return links::ReplyMatch::not_mine;
             }
             reply = std::move(*frame);
             return links::ReplyMatch::mine;
           },
       .timeout = kReplyTimeout,
       .attempts = kAttempts});
  return reply;
}

float PowercubeWrist::read_float(pc::Module module, pc::Parameter parameter) {
  return pc::float_from_bits(*pc::reply_value(ask(module, pc::get_data(parameter)), parameter));
}

std::uint32_t PowercubeWrist::read_state(pc::Module module) {
  return *pc::reply_value(ask(module, pc::get_data(pc::Parameter::state)), pc::Parameter::state);
}

double ModuleReach::clamp(double degrees) const { return min < max ? std::clamp(degrees, min, max) : degrees; }

std::array<ModuleReach, 2> PowercubeWrist::start() {
  for (const pc::Module module : {pc::Module::pan, pc::Module::tilt}) {
    try {
      (void)read_float(module, pc::Parameter::position);
    } catch (const links::ExchangeError& e) {
      if (e.kind() == links::ExchangeError::Kind::stopped) throw;
      throw links::ExchangeError(e.kind(), std::string("the ") + module_name(module) + " does not answer");
    }
  }
  // A step beyond its limits is a module's error: targets are kept within them.
  std::array<ModuleReach, 2> reach{};
  for (std::size_t i = 0; i < reach.size(); ++i) {
    const pc::Module module = i == 0 ? pc::Module::pan : pc::Module::tilt;
    reach[i] = {pc::degrees(read_float(module, pc::Parameter::min_position)),
                pc::degrees(read_float(module, pc::Parameter::max_position))};
  }
  for (const pc::Module module : {pc::Module::pan, pc::Module::tilt}) ask(module, pc::reset_data());
  home(pc::Module::pan);
  home(pc::Module::tilt);
  return reach;
}

void PowercubeWrist::home(pc::Module module) {
  ask(module, pc::home_data());
  const auto give_up = links::deadline_in(kHomingTimeout);
  for (std::uint32_t state = read_state(module); (state & pc::state_bit::homed) == 0; state = read_state(module)) {
    if ((state & pc::state_bit::error) != 0) {
      throw std::runtime_error(std::string("the ") + module_name(module) + " reports an error while homing");
    }
    if (links::LinkClock::now() >= give_up) {
      throw std::runtime_error(std::string("the ") + module_name(module) + " did not report itself homed within " +
                               std::to_string(kHomingTimeout.count() / 1000) + " s");
    }
    // Waiting on the line rather than sleeping: a stop ends it at once.
    (void)exchanger_.next(links::deadline_in(kHomingPoll));
  }
}

}  // namespace playerkit::drivers::amtecpowercube
