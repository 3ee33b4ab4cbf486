#include "families/garminnmea/emulator/garminnmea_emulator.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

#include "families/garminnmea/protocol/gps_fix_tracker.hpp"
#include "families/garminnmea/protocol/utm.hpp"
#include "framing/nmea_format.hpp"

namespace playerkit::emulators {

namespace gps = hardware::garminnmea;

namespace {

constexpr double kDay = 86400.0;

Duration seconds_as_duration(double seconds) {
  return std::chrono::duration_cast<Duration>(std::chrono::duration<double>(seconds));
}

std::string printed(const char* format, auto... values) {
  char text[96];
  std::snprintf(text, sizeof text, format, values...);
  return text;
}

// The time of day a recorded sentence carries, if it is one that does.
std::optional<double> recorded_time(const std::string& line) {
  const auto bytes = std::vector<std::uint8_t>(line.begin(), line.end());
  const auto sentence = gps::parse_sentence(framing::nmea_body(bytes));
  if (!sentence) return std::nullopt;
  if (const auto* gga = std::get_if<gps::Gga>(&*sentence)) return gga->time;
  if (const auto* rmc = std::get_if<gps::Rmc>(&*sentence)) return rmc->time;
  if (const auto* gll = std::get_if<gps::Gll>(&*sentence)) return gll->time;
  return std::nullopt;
}

}  // namespace

GarminNmeaEmulator::GarminNmeaEmulator(GarminNmeaGenerated generated) : generated_(std::move(generated)) {
  if (generated_.period <= Duration::zero()) throw std::invalid_argument("garminnmea emulator: the period must be above 0");
}

GarminNmeaEmulator::GarminNmeaEmulator(GarminNmeaPlayback playback) : playing_(true), playback_(std::move(playback)) {
  std::erase_if(playback_.sentences, [](const std::string& line) { return line.empty() || line[0] != '$'; });
  if (playback_.sentences.empty()) throw std::invalid_argument("garminnmea emulator: the log has no NMEA sentence");
  if (!(playback_.rate > 0)) throw std::invalid_argument("garminnmea emulator: the rate must be above 0");
  next_due_ = loop_start_ = std::max(Duration::zero(), playback_.start);
}

void GarminNmeaEmulator::receive(std::span<const std::uint8_t> bytes, Duration now, int host_baud) {
  // RTCM corrections, or anything else: the receiver ignores them (sheet §6.6).
  bytes_received_ += bytes.size();
  if (host_baud != 0 && !bytes.empty()) host_baud_ = host_baud;
  advance(now);
}

void GarminNmeaEmulator::host_disconnected(Duration /*now*/) { host_baud_ = 0; }

void GarminNmeaEmulator::garble(std::vector<std::uint8_t>& bytes) {
  // What a UART at the wrong speed makes of a character: never printable
  // text, so no sentence can appear in it.
  for (std::uint8_t& byte : bytes) {
    noise_state_ ^= noise_state_ << 13;
    noise_state_ ^= noise_state_ >> 17;
    noise_state_ ^= noise_state_ << 5;
    byte = static_cast<std::uint8_t>(0x80 | (noise_state_ & 0x7F));
  }
}

void GarminNmeaEmulator::advance(Duration now) {
  if (playing_) {
    while (next_due_ <= now) play_due();
    return;
  }
  while (true) {
    const Duration line_due = pending_.empty() ? Duration::max() : pending_.front().first;
    if (std::min(line_due, next_due_) > now) return;
    if (line_due <= next_due_) {
      send(pending_.front().second);
      pending_.pop_front();
    } else {
      generate_cycle(next_due_);
      next_due_ += generated_.period;
    }
  }
}

Duration GarminNmeaEmulator::next_deadline() const {
  if (playing_ || pending_.empty()) return next_due_;
  return std::min(next_due_, pending_.front().first);
}

std::vector<Telegram> GarminNmeaEmulator::take_output() { return std::exchange(output_, {}); }

void GarminNmeaEmulator::send(const std::string& line) {
  std::vector<std::uint8_t> bytes(line.begin(), line.end());
  if (baud() != 0 && host_baud_ != 0 && host_baud_ != baud()) {
    bytes.push_back('\r');
    bytes.push_back('\n');
    garble(bytes);
    output_.push_back({std::move(bytes), false});
  } else {
    // The sentence and its CR LF go out as two telegrams: a "bad checksum" fault corrupts a telegram's last byte,
    // which must be the second digit of `*hh`, not the LF (a lost LF is a framing fault: it merged two sentences,
    // and the 1.5 driver's "bad checksum: warned, still parsed" of sheet §6.7 was never what it saw).
    const bool has_checksum = line.size() >= 3 && line[line.size() - 3] == '*';
    output_.push_back({std::move(bytes), has_checksum});
    output_.push_back({{'\r', '\n'}, false});
  }
  ++sentences_sent_;
}

std::string GarminNmeaEmulator::describe() const {
  if (playing_) {
    return "Garmin NMEA receiver playing a log of " + std::to_string(playback_.sentences.size()) + " sentences at " +
           printed("%g", playback_.rate) + "x" + (playback_.loop ? ", looped" : "") + ", " +
           std::to_string(sentences_sent_) + " sent" + (finished() ? ", finished" : "");
  }
  return "Garmin NMEA receiver, " + std::to_string(cycles_) + " cycles of " +
         printed("%g", std::chrono::duration<double>(generated_.period).count()) + " s" +
         (generated_.fix ? ", fixed" : ", searching");
}

// --- playback

void GarminNmeaEmulator::play_due() {
  const std::string& line = playback_.sentences[next_line_];
  if (next_line_ == 0) {
    if (const auto time = recorded_time(line)) loop_first_time_ = last_time_ = *time;
  }
  send(line);
  ++next_line_;
  if (next_line_ < playback_.sentences.size()) {
    schedule_after_playing(line.size() + 2);
    return;
  }
  ++cycles_;
  if (!playback_.loop) {
    next_due_ = Duration::max();
    return;
  }
  // Again from the top, a second (of the log's time) after the last line.
  next_line_ = 0;
  loop_start_ = next_due_ + seconds_as_duration(1.0 / playback_.rate);
  loop_first_time_ = -1;
  day_offset_ = 0;
  last_time_ = -1;
  next_due_ = loop_start_;
}

void GarminNmeaEmulator::schedule_after_playing(std::size_t length) {
  // The bytes just sent take their time on the line (10 bits a character).
  const double baud = playback_.baud > 0 ? playback_.baud : 4800.0;
  Duration due = next_due_ + seconds_as_duration(static_cast<double>(length) * 10.0 / baud / playback_.rate);
  if (const auto time = recorded_time(playback_.sentences[next_line_])) {
    double unwrapped = *time + day_offset_;
    if (last_time_ >= 0 && unwrapped < last_time_ - kDay / 2) {
      day_offset_ += kDay;
      unwrapped += kDay;
    }
    if (loop_first_time_ < 0) loop_first_time_ = unwrapped;
    // Sentences of a later second wait for it; a GLL stamped a second
    // earlier than the RMC before it does not.
    if (unwrapped > last_time_) {
      due = std::max(due, loop_start_ + seconds_as_duration((unwrapped - loop_first_time_) / playback_.rate));
      last_time_ = unwrapped;
    }
  }
  next_due_ = due;
}

// --- generation

std::vector<std::string> GarminNmeaEmulator::cycle_bodies(const GarminNmeaGenerated& s, double time_of_day,
                                                          const gps::Date& date, double latitude, double longitude) {
  const std::string time = gps::format_time(time_of_day, 2);
  const std::string position = gps::format_angle(latitude, false, s.decimals) + (latitude < 0 ? ",S," : ",N,") +
                               gps::format_angle(longitude, true, s.decimals) + (longitude < 0 ? ",W" : ",E");
  const char* status = s.fix ? "A" : "V";
  const int satellites = std::clamp(s.satellites, 0, 12);
  std::vector<std::string> bodies;
  bodies.push_back("GPRMC," + time + "," + status + "," + position + ",000.0,000.0," + gps::format_date(date) +
                   ",013.2,E");
  bodies.push_back("GPGGA," + time + "," + position + printed(",%d,%02d,%.1f,%.1f,M,0.0,M,,", s.fix ? s.quality : 0,
                                                               s.fix ? satellites : 0, s.hdop, s.altitude));
  std::string gsa = std::string("GPGSA,A,") + (s.fix ? "3" : "1");
  for (int i = 1; i <= 12; ++i) gsa += i <= satellites && s.fix ? printed(",%02d", i) : std::string(",");
  gsa += s.fix ? printed(",%.1f,%.1f,%.1f", s.hdop * 1.5, s.hdop, s.hdop * 1.2) : std::string(",,,");
  bodies.push_back(gsa);
  const int messages = std::max(1, (satellites + 3) / 4);
  for (int m = 1; m <= messages; ++m) {
    std::string gsv = printed("GPGSV,%d,%d,%02d", messages, m, satellites);
    for (int i = (m - 1) * 4 + 1; i <= std::min(satellites, m * 4); ++i) {
      gsv += printed(",%02d,%02d,%03d,%02d", i, 10 + (i * 37) % 80, (i * 97) % 360, s.fix ? 30 + i % 20 : 0);
    }
    bodies.push_back(gsv);
  }
  bodies.push_back(printed("PGRME,%.1f,M,%.1f,M,%.1f,M", s.horizontal_error, s.vertical_error,
                           std::hypot(s.horizontal_error, s.vertical_error)));
  bodies.push_back("GPGLL," + position + "," + time + "," + status);
  bodies.push_back(printed("PGRMZ,%ld,f,%d", std::lround(s.altitude / 0.3048), s.fix ? 3 : 1));
  bodies.push_back("PGRMM,WGS 84");
  return bodies;
}

void GarminNmeaEmulator::generate_cycle(Duration at) {
  const double elapsed = std::chrono::duration<double>(generated_.period).count() * static_cast<double>(cycles_);
  const double since_midnight = generated_.start_time_of_day + elapsed;
  const auto day = gps::days_since_epoch(generated_.date) + static_cast<std::int64_t>(std::floor(since_midnight / kDay));
  const geometry::Pose2 pose = generated_.pose_source ? generated_.pose_source() : geometry::Pose2{};
  // The map's metres are UTM metres in the origin's zone.
  gps::Utm origin = gps::to_utm(generated_.origin_latitude, generated_.origin_longitude);
  origin.easting += pose.x;
  origin.northing += pose.y;
  const gps::LatLon here = gps::from_utm(origin);
  last_latitude_ = here.latitude;
  last_longitude_ = here.longitude;
  const auto bodies =
      cycle_bodies(generated_, std::fmod(since_midnight, kDay), gps::date_from_days(day), here.latitude, here.longitude);
  // The first line at once, the rest over four fifths of the cycle.
  const Duration spacing = generated_.period * 4 / 5 / static_cast<long>(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const auto bytes = framing::nmea_sentence(bodies[i]);
    pending_.emplace_back(at + spacing * static_cast<long>(i), std::string(bytes.begin(), bytes.end() - 2));
  }
  ++cycles_;
}

}  // namespace playerkit::emulators
