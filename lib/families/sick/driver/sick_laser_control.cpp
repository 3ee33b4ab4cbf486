#include "families/sick/driver/sick_laser_control.hpp"

#include <utility>

#include "families/sick/protocol/replies.hpp"
#include "links/link_error.hpp"

namespace playerkit::drivers::sick_laser {

namespace sick = hardware::sick;

namespace {

std::string join_rates(const std::vector<int>& rates) {
  std::string text;
  for (const int rate : rates) {
    if (!text.empty()) text += ", ";
    text += std::to_string(rate);
  }
  return text;
}

std::string variant_text(const sick::Variant& variant) {
  const int r = variant.resolution_cdeg;
  return std::to_string(variant.width_deg) + " deg at " + std::to_string(r / 100) + "." +
         (r % 100 < 10 ? "0" : "") + std::to_string(r % 100) + " deg";
}

}  // namespace

std::string model_name(Model model) { return model == Model::lms200 ? "SICK LMS 200" : "SICK PLS"; }

SickLaserControl::SickLaserControl(SickSession& session, Model model, std::string port,
                                   std::chrono::milliseconds reply_timeout)
    : session_(session), model_(model), port_(std::move(port)), reply_timeout_(reply_timeout) {}

std::string SickLaserControl::failure(const std::string& what) const { return port_ + ": " + what; }

sick::Reply SickLaserControl::ask(const sick::Request& request, std::uint8_t expected,
                                  const std::string& step) {
  // A reply lost to line noise is asked for again; every step here may be
  // repeated without harm (T2, which may not, does not come through here).
  try {
    return session_.exchange(request, expected, reply_timeout_, kAttempts);
  } catch (const SickExchangeError& e) {
    if (e.kind() == SickExchangeError::Kind::stopped) throw;
    throw SickSetupError(failure(step + ": " + e.what()));
  }
}

void SickLaserControl::enter_installation_mode() {
  const std::string password(sick::installation_password(model_));
  const sick::ModeReply mode = sick::parse_mode_reply(
      session_.exchange(sick::InstallationModeRequest{password}, sick::kSwitchModeReply, reply_timeout_, kAttempts));
  if (mode.result == sick::ModeResult::wrong_password) {
    const std::string other = model_ == Model::lms200 ? "a SICK PLS (driver sickpls)" : "a SICK LMS (driver sicklms200)";
    throw SickSetupError(failure("the laser refused the password " + password + " (A0 01): is it " + other + "?"));
  }
  if (mode.result != sick::ModeResult::ok) {
    throw SickSetupError(failure("the laser reports a fault entering installation mode (A0 02)"));
  }
}

int SickLaserControl::find(const std::vector<int>& rates) {
  auto& link = session_.link();
  const bool has_speed = link.baud() > 0;
  std::string last_problem;
  for (const int rate : has_speed ? rates : std::vector<int>{0}) {
    if (rate > 0) link.set_baud(rate);
    try {
      enter_installation_mode();
      return rate;
    } catch (const SickExchangeError& e) {
      if (e.kind() == SickExchangeError::Kind::stopped) throw;
      last_problem = e.what();
    } catch (const sick::TelegramError& e) {
      last_problem = e.what();
    }
  }
  const std::string tried = has_speed ? " at " + join_rates(rates) + " baud" : "";
  // The exchange's message says how many tries of how long.
  throw SickSetupError(failure("no answer from the " + model_name(model_) + tried + " (" + last_problem +
                               (has_speed ? " at each speed" : "") + "): is it powered and connected to this port?"));
}

void SickLaserControl::switch_rate(int baud) {
  auto& link = session_.link();
  if (link.baud() == 0 || link.baud() == baud) return;
  const int old_baud = link.baud();
  // Sent once: a laser whose reply was lost has switched all the same, and
  // a second T2 at the old speed would be noise to it.
  std::string lost_reply;
  try {
    const sick::ModeReply reply = sick::parse_mode_reply(
        session_.exchange(sick::BaudRateRequest{baud}, sick::kSwitchModeReply, reply_timeout_));
    if (reply.result != sick::ModeResult::ok) {
      throw SickSetupError(failure("the laser refused " + std::to_string(baud) + " baud"));
    }
  } catch (const SickExchangeError& e) {
    if (e.kind() != SickExchangeError::Kind::no_reply) {
      throw SickSetupError(failure("switching to " + std::to_string(baud) + " baud: " + e.what()));
    }
    lost_reply = e.what();
  }
  link.set_baud(baud);
  // The laser changes speed after its reply; T1 proves both ends agree (an
  // adapter may not really do 500000).
  try {
    enter_installation_mode();
    return;
  } catch (const SickExchangeError& e) {
    if (e.kind() == SickExchangeError::Kind::stopped) throw;
  }
  if (!lost_reply.empty()) {
    throw SickSetupError(failure("switching from " + std::to_string(old_baud) + " to " + std::to_string(baud) +
                                 " baud: " + lost_reply + ", and no answer at either speed since"));
  }
  throw SickSetupError(failure("the laser accepted " + std::to_string(baud) +
                               " baud but does not answer at that speed (it was at " +
                               std::to_string(old_baud) +
                               "): does the serial adapter support it?"));
}

std::string SickLaserControl::read_type() {
  return sick::parse_type_reply(ask(sick::GetTypeRequest{}, sick::kTypeReply, "reading the type")).trimmed();
}

sick::Unit SickLaserControl::configure(const ScanConfig& config) {
  if (model_ == Model::pls) return sick::Unit::centimetre;  // nothing to set on a PLS
  const sick::Variant variant = device_variant(config, model_);
  const sick::VariantReply set =
      sick::parse_variant_reply(ask(sick::SetVariantRequest{variant}, sick::kVariantReply, "setting the variant"));
  if (!set.accepted) {
    throw SickSetupError(failure("the laser refused the variant " + variant_text(variant) +
                                 " (BB 00; it keeps " + variant_text(set.variant) + ")"));
  }
  sick::ConfigBlock block =
      sick::parse_config_reply(ask(sick::GetConfigRequest{}, sick::kConfigReply, "reading the configuration")).config;
  // Only the two blocks the driver owns change; the rest is the laser's.
  block.set_measuring_mode(config.intensity ? sick::MeasuringMode::reflector_levels
                                            : sick::MeasuringMode::fields_and_dazzle);
  block.set_unit(device_unit(config, model_));
  const sick::SetConfigReply written = sick::parse_set_config_reply(
      ask(sick::SetConfigRequest{block}, sick::kSetConfigReply, "writing the configuration"));
  if (!written.accepted || written.config.unit() != block.unit() ||
      written.config.measuring_mode() != block.measuring_mode()) {
    throw SickSetupError(failure("the laser refused the configuration (F7 " +
                                 std::string(written.accepted ? "01" : "00") + ") with measuring mode " +
                                 std::to_string(static_cast<int>(block.measuring_mode())) + " and unit " +
                                 std::to_string(static_cast<int>(block.unit()))));
  }
  return written.config.unit();
}

void SickLaserControl::stream(const ScanConfig& config) {
  const sick::Request request = stream_request(config, model_);
  const sick::ModeReply reply =
      sick::parse_mode_reply(ask(request, sick::kSwitchModeReply, "starting the stream"));
  if (reply.result != sick::ModeResult::ok) {
    throw SickSetupError(failure("the laser refused " + sick::describe(request)));
  }
}

void SickLaserControl::stop_streaming() {
  try {
    enter_installation_mode();
  } catch (const SickExchangeError& e) {
    if (e.kind() == SickExchangeError::Kind::stopped) throw;
    throw SickSetupError(failure(std::string("stopping the stream: ") + e.what()));
  }
}

LaserState SickLaserControl::bring_up(const ScanConfig& config, int rate, const std::vector<int>& probe_rates) {
  try {
    find(probe_rates);
    switch_rate(rate);
    LaserState state;
    if (model_ == Model::lms200) state.type = read_type();
    state.unit = configure(config);
    stream(config);
    state.baud = session_.link().baud();
    return state;
  } catch (const sick::TelegramError& e) {
    throw SickSetupError(failure(std::string("the laser's reply makes no sense: ") + e.what()));
  }
}

}  // namespace playerkit::drivers::sick_laser
