#pragma once
// The steps that bring a SICK laser from wherever it is to streaming the
// scan asked for (sicklms200.md §1.1 and §2.3, sickpls.md §2.1), each one
// request and its checked reply, each bounded by the reply timeout:
//
//   find        T1 (installation mode, the model's password) at each
//               candidate speed in turn until the laser answers
//   switch_rate T2 to the wanted speed, the line follows, T1 confirms
//   read_type   T3 (LMS 200)
//   configure   T4 variant, T5 get and T6 set configuration (LMS 200):
//               measuring mode (reflector levels or not) and unit
//   stream      T7 all values, or T8 a subrange
//
// Every request is sent up to kAttempts times while no reply comes (T2
// once: see switch_rate). Failures are SickSetupErrors whose message names
// the port and says what the laser did (or did not do), ready for a log
// line or a DriverError.

#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

#include "families/sick/driver/sick_scan_config.hpp"
#include "families/sick/driver/sick_session.hpp"
#include "families/sick/protocol/codes.hpp"

namespace playerkit::drivers::sick_laser {

class SickSetupError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// What the laser is doing after a successful bring-up.
struct LaserState {
  int baud = 0;      // the line's speed; 0 on a link without one (TCP)
  std::string type;  // the BA text (LMS 200), trailing spaces removed
  hardware::sick::Unit unit = hardware::sick::Unit::millimetre;  // as the laser confirmed it
};

// "SICK LMS 200", "SICK PLS"
std::string model_name(Model model);

class SickLaserControl {
 public:
  // Tries per request before a step fails (1.5 sent T1 twice at each
  // speed): a reply may be lost to line noise.
  static constexpr int kAttempts = 2;

  SickLaserControl(SickSession& session, Model model, std::string port,
                   std::chrono::milliseconds reply_timeout);

  // Returns the speed it answered at (0 on a link without speeds, where
  // only one T1 is sent).
  int find(const std::vector<int>& rates);
  void switch_rate(int baud);
  std::string read_type();
  hardware::sick::Unit configure(const ScanConfig& config);
  void stream(const ScanConfig& config);
  // T1: the stream stops and the laser waits in installation mode.
  void stop_streaming();

  // find, switch_rate, read_type, configure and stream.
  LaserState bring_up(const ScanConfig& config, int rate, const std::vector<int>& probe_rates);

 private:
  // exchange() with failures as SickSetupErrors saying `step`.
  hardware::sick::Reply ask(const hardware::sick::Request& request, std::uint8_t expected,
                            const std::string& step);
  void enter_installation_mode();
  [[nodiscard]] std::string failure(const std::string& what) const;

  SickSession& session_;
  Model model_;
  std::string port_;
  std::chrono::milliseconds reply_timeout_;
};

}  // namespace playerkit::drivers::sick_laser
