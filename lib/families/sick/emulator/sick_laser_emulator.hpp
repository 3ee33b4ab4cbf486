#pragma once
// The protocol side of an emulated SICK laser, shared by the LMS 200 and the
// PLS (sick_lms200_emulator.hpp, sick_pls_emulator.hpp), written from
// sicklms200.md §6 and sickpls.md §6:
//
// * requests `02 00 LEN body CRC` are answered with one telegram each,
//   `02 80 LEN code data 10 CRC`, after an ACK byte 0x06 (its own Telegram,
//   has_checksum false); a bad CRC gets a NAK 0x15 and no answer;
// * any request stops streaming at once, before it is answered;
// * T1 with the model's password enters installation mode (A0 00; a wrong
//   password A0 01); T2 answers A0 00 at the old speed, then switches;
// * T7/T8 answer A0 00 and stream B0/B7 scans, paced by the slower of the
//   mirror (one scan per rotation) and the line (bits per byte / baud per
//   telegram byte), so never faster than the real line carries them;
// * unknown commands, and well-framed ones with a wrong length, get 92 00;
// * nothing is sent unsolicited besides the stream;
// * bytes the host sent at another speed than the device's are line noise;
// * a host disconnecting changes nothing (the real devices keep streaming).
//
// A request's bytes still arriving hold the stream back (the host flushed
// its input before writing it and takes the next telegram as its answer),
// and a partial telegram is dropped after 100 ms of silence.

#include "emulators/device_emulator.hpp"
#include "families/sick/emulator/sick_emulator_options.hpp"
#include "families/sick/emulator/sick_laser_scene.hpp"
#include "families/sick/protocol/codes.hpp"
#include "families/sick/protocol/config_block.hpp"
#include "families/sick/protocol/requests.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace playerkit::emulators {

// What differs between the emulated models.
struct SickModelProfile {
  hardware::sick::Model model = hardware::sick::Model::lms200;
  std::string_view display_name;    // "SICK LMS 200"
  int bits_per_byte = 10;           // start + 8 data (+ parity) + stop
  Duration rotation_period{};       // one scan of the mirror
  bool configurable = true;         // answers get type, variant, get/set configuration
};

class SickLaserEmulator : public DeviceEmulator {
 public:
  enum class Mode { idle, installation, streaming_all, streaming_subrange };

  void receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) override;
  void advance(Duration now) override;
  [[nodiscard]] Duration next_deadline() const override;
  std::vector<Telegram> take_output() override;
  void host_disconnected(Duration now) override;
  [[nodiscard]] int baud() const override { return options_.model_baud_rates ? baud_ : 0; }
  [[nodiscard]] std::string describe() const override;

  // The device's state, for tests and statistics.
  [[nodiscard]] Mode mode() const { return mode_; }
  [[nodiscard]] int line_baud() const { return baud_; }  // even when not modelling rates
  [[nodiscard]] const hardware::sick::Variant& variant() const { return variant_; }
  [[nodiscard]] const hardware::sick::ConfigBlock& config() const { return config_; }
  [[nodiscard]] hardware::sick::Unit unit() const;
  [[nodiscard]] double max_range_m() const;
  [[nodiscard]] std::uint64_t scans_sent() const { return scans_sent_; }
  [[nodiscard]] std::uint64_t requests_answered() const { return requests_answered_; }
  [[nodiscard]] std::uint64_t noise_bytes() const { return noise_bytes_; }
  // Time between two stream telegrams at the current speed and variant.
  [[nodiscard]] Duration scan_period() const;
  // How long `bytes` take on the line at the current speed.
  [[nodiscard]] Duration line_time(std::size_t bytes) const;

  static constexpr Duration kInterByteTimeout = std::chrono::milliseconds(100);

 protected:
  // Throws std::invalid_argument for options the device cannot have: a
  // power-up speed with no rate code, a type text over 20 characters, a
  // non-positive max range, bad reflectors or noise (SickLaserScene).
  SickLaserEmulator(const SickModelProfile& profile, SickEmulatorOptions options);

 private:
  void handle_telegram(std::span<const std::uint8_t> telegram, Duration now);
  std::vector<std::uint8_t> answer(const hardware::sick::Request& request, Duration now);
  std::vector<std::uint8_t> set_configuration(const hardware::sick::ConfigBlock& requested);
  std::vector<std::uint8_t> start_stream(Mode mode, hardware::sick::Subrange range, Duration now);
  void send(std::vector<std::uint8_t> reply);
  void send_scan(Duration now);
  [[nodiscard]] std::size_t stream_telegram_size() const;
  [[nodiscard]] bool streaming() const {
    return mode_ == Mode::streaming_all || mode_ == Mode::streaming_subrange;
  }

  SickModelProfile profile_;
  SickEmulatorOptions options_;
  SickLaserScene scene_;
  std::string type_text_;

  int baud_;
  Mode mode_ = Mode::idle;
  hardware::sick::Variant variant_;
  hardware::sick::ConfigBlock config_;
  hardware::sick::Subrange subrange_;
  Duration next_scan_{};

  std::vector<std::uint8_t> received_;  // the front of a request still arriving
  Duration last_byte_{};
  std::vector<Telegram> output_;

  std::uint64_t scans_sent_ = 0;
  std::uint64_t requests_answered_ = 0;
  std::uint64_t noise_bytes_ = 0;
};

}  // namespace playerkit::emulators
