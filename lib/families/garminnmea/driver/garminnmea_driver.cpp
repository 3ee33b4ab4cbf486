// The garminnmea driver: a GPS receiver as a gps device. The kit's
// SerialDeviceDriver opens the port and wakes this driver when sentences
// arrive; what is here is reading them (framing::NmeaFormat drops and counts
// bad checksums), making fixes (GpsFixTracker, gpsd's way) and mapping each
// fix to player_gps_data_t (garminnmea.md §3), with its UTM in its own zone.
#include "families/garminnmea/driver/garminnmea_driver.hpp"

#include <cmath>
#include <memory>
#include <optional>

#include "families/garminnmea/driver/dgps_relay.hpp"
#include "families/garminnmea/driver/garminnmea_options.hpp"
#include "families/garminnmea/protocol/gps_fix_tracker.hpp"
#include "families/garminnmea/protocol/utm.hpp"
#include "framing/nmea_format.hpp"
#include "hardware_driver/serial_device_driver.hpp"
#include "links/framed_reader.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/gps.hpp"

namespace playerkit::drivers {

namespace {

using namespace std::chrono_literals;
namespace gps = hardware::garminnmea;

// 1.5 gave a silent receiver about 10 s at setup (garminnmea.md §1); a
// receiver sends every second, so 5 s without a sentence later is a lost one.
constexpr auto kFirstSentenceWait = 10s;
constexpr auto kSilenceLimit = 5s;
// RTCM corrections come about once a second; looking for them this often
// costs nothing and delays them little.
constexpr auto kDgpsLook = 200ms;
// Sentences handled in one pass before the thread looks at requests again.
constexpr int kSentencesPerPass = 32;
constexpr std::size_t kLongestSentence = 128;

template <typename T>
T clamped(double value) {
  const double low = static_cast<double>(std::numeric_limits<T>::min());
  const double high = static_cast<double>(std::numeric_limits<T>::max());
  return static_cast<T>(std::clamp(std::round(value), low, high));
}

protocol::GpsData wire_fix(const gps::GpsFix& fix) {
  protocol::GpsData data;
  data.time_sec = clamped<std::uint32_t>(static_cast<double>(fix.time_sec));
  data.time_usec = fix.time_usec;
  if (fix.has_position) {
    data.latitude = clamped<std::int32_t>(fix.latitude * 216000.0);
    data.longitude = clamped<std::int32_t>(fix.longitude * 216000.0);
    const gps::Utm utm = gps::to_utm(fix.latitude, fix.longitude);
    data.utm_e = clamped<std::int32_t>(utm.easting * 100.0);
    data.utm_n = clamped<std::int32_t>(utm.northing * 100.0);
  }
  data.altitude = clamped<std::int32_t>(fix.altitude * 1000.0);
  data.quality = clamped<std::uint8_t>(fix.quality);
  data.num_sats = clamped<std::uint8_t>(fix.satellites);
  data.hdop = clamped<std::uint16_t>(fix.hdop * 10.0);
  data.err_horz = clamped<std::uint32_t>(fix.horizontal_error * 1000.0);
  data.err_vert = clamped<std::uint32_t>(fix.vertical_error * 1000.0);
  return data;
}

class GarminNmeaDriver final : public hardware_driver::SerialDeviceDriver {
 public:
  explicit GarminNmeaDriver(garminnmea::GarminNmeaSettings settings)
      : SerialDeviceDriver(settings.port, {.baud = settings.baud}, {}), settings_(std::move(settings)) {}

 private:
  // --- the kit's hooks
  void start_device(links::ByteLink& link, bool /*recovering*/) override {
    reader_ = std::make_unique<links::FramedReader>(link, format_, kLongestSentence);
    // The receiver streams on its own: the first good sentence is the handshake.
    const auto first_wait_end = Clock::now() + kFirstSentenceWait;
    std::optional<std::vector<std::uint8_t>> sentence;
    while (!sentence && Clock::now() < first_wait_end) {
      if (stopping()) throw hardware_driver::Stopping();
      sentence = reader_->next(std::min(first_wait_end, Clock::now() + 100ms));
      if (!sentence) ++own_timeouts_;
    }
    if (!sentence) {
      throw std::runtime_error("no NMEA sentence in " + std::to_string(kFirstSentenceWait.count()) + " s at " +
                               std::to_string(settings_.baud) + " baud (is the receiver on, and is baud right?)");
    }
    if (settings_.dgps_enable && !dgps_) start_dgps();
    take(*sentence);
    more_buffered_ = true;
  }

  void serve(links::ByteLink& link, const core::Wakeup::Woken& woke) override {
    if (woke.readable || more_buffered_) {
      more_buffered_ = false;
      auto look = woke.readable ? Clock::now() + 1ms : Clock::now();
      for (int i = 0; i < kSentencesPerPass; ++i) {
        auto sentence = reader_->next(look);
        if (!sentence) {
          ++own_timeouts_;
          break;
        }
        take(*sentence);
        look = Clock::now();
        more_buffered_ = i + 1 == kSentencesPerPass;
      }
    }
    if (dgps_) relay_corrections(link);
    device().service_requests();
    const auto silence = Clock::now() - last_sentence_;
    if (silence > kSilenceLimit) {
      throw hardware_driver::DeviceLost(
          "no NMEA sentence for " + std::to_string(std::chrono::duration_cast<std::chrono::seconds>(silence).count()) +
          " s");
    }
  }

  [[nodiscard]] Clock::time_point next_deadline() const override {
    if (more_buffered_) return Clock::now();
    const auto lost_at = last_sentence_ + kSilenceLimit + 1ms;
    return dgps_ ? std::min(lost_at, Clock::now() + kDgpsLook) : lost_at;
  }
  void link_closing() noexcept override { reader_.reset(); }
  [[nodiscard]] std::string subject() const override { return "the GPS receiver on " + port(); }
  [[nodiscard]] std::uint64_t own_timeouts() const override { return own_timeouts_; }
  [[nodiscard]] std::vector<core::DriverCounter> protocol_counters() const override {
    return {{"sentences", tracker_.sentences_used()},
            {"sentences_ignored", tracker_.sentences_ignored()},
            {"fixes", fixes_},
            {"no_fix_reports", no_fix_reports_},
            {"dgps_bytes", dgps_bytes_}};
  }

  // --- receiver -> Player
  void take(std::span<const std::uint8_t> sentence) {
    last_sentence_ = Clock::now();
    const auto fix = tracker_.take(framing::nmea_body(sentence));
    if (!fix) return;
    ++(fix->has_position ? fixes_ : no_fix_reports_);
    device().publish(protocol::encode(wire_fix(*fix)));
  }

  // --- corrections -> receiver
  void start_dgps() {
    try {
      dgps_ = std::make_unique<garminnmea::DgpsRelay>(settings_.dgps_group, settings_.dgps_port,
                                                       settings_.dgps_bind);
      if (!dgps_->warning().empty()) device().logger().warning(device().name() + ": " + dgps_->warning());
    } catch (const std::runtime_error& e) {
      // 1.5 refused to start; a receiver without corrections still gives fixes.
      device().logger().warning(device().name() + ": " + e.what() + "; running without DGPS corrections");
      settings_.dgps_enable = false;
    }
  }

  void relay_corrections(links::ByteLink& link) {
    for (const auto& datagram : dgps_->take_datagrams()) {
      link.write_all(datagram, links::deadline_in(1s));
      dgps_bytes_ += datagram.size();
    }
  }

  garminnmea::GarminNmeaSettings settings_;
  const framing::NmeaFormat format_{};
  std::unique_ptr<links::FramedReader> reader_;
  gps::GpsFixTracker tracker_;
  std::unique_ptr<garminnmea::DgpsRelay> dgps_;
  Clock::time_point last_sentence_ = Clock::now();
  bool more_buffered_ = false;
  std::uint64_t own_timeouts_ = 0;
  std::uint64_t fixes_ = 0;
  std::uint64_t no_fix_reports_ = 0;
  std::uint64_t dgps_bytes_ = 0;
};

}  // namespace

core::DriverSpec garminnmea_driver_spec() {
  return {
      .name = "garminnmea",
      .interfaces = {protocol::kGpsCode},
      .access = protocol::Access::kAll,
      .factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
        return std::make_unique<GarminNmeaDriver>(garminnmea::read_garminnmea_settings(context.section));
      },
      .limits = {},
      .summary = "Garmin (any NMEA 0183) GPS receiver (gps)",
      .family = "garminnmea",
      .doc = {.manual_section = "7.11",
              .needs_hardware = true,
              .options = {},
              .requests = {},
              .example = "gps:0 ( driver \"garminnmea\" port \"/dev/ttyS0\" dgps_enable 0 )",
              .schema = garminnmea::garminnmea_option_schema()},
  };
}

}  // namespace playerkit::drivers
