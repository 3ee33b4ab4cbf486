#pragma once
// The Pioneer gripper: paddles that open and close and a lift that rises
// and lowers, each taking a full stroke's travel time, reported through the
// state bits (SIP TIMER high byte) and beam bits (SIP DIGIN) of p2os.md §3.3.

#include <cstdint>

namespace playerkit::emulators::p2os {

class GripperModel {
 public:
  // Starts stored: paddles closed, lift up.
  explicit GripperModel(double travel_seconds);

  // A GRIPPER argument (families/p2os/protocol/gripper.hpp); unknown ones are ignored.
  // GRIPpress closes, LIFTcarry lifts: their GRIPPERVAL amount is not modelled.
  void command(int gripper_command);
  void run(double seconds);

  std::uint8_t state_bits() const;
  std::uint8_t beam_bits() const;
  void set_beams(bool outer_obstructed, bool inner_obstructed);

  double paddle_opening() const { return paddles_; }  // 0 closed ... 1 open
  double lift_height() const { return lift_; }        // 0 down ... 1 up
  bool moving() const { return paddle_direction_ != 0 || lift_direction_ != 0; }

 private:
  static void move(double& position, int& direction, double amount);
  static int towards(double position, int direction);

  double travel_seconds_;
  double paddles_ = 0.0;
  double lift_ = 1.0;
  int paddle_direction_ = 0;
  int lift_direction_ = 0;
  bool outer_beam_ = false;
  bool inner_beam_ = false;
};

}  // namespace playerkit::emulators::p2os
