// "Who are you?" on a line, NMEA style: a receiver never answers, it talks,
// so the probe listens, and two sentences with good checksums are a
// receiver (one could be chance at the wrong speed). It sends only an empty
// line first (CR LF), which receivers ignore, so that a device that models
// its line speed hears which one the host is at.
#include <algorithm>
#include <array>
#include <chrono>
#include <set>
#include <string>

#include "families/garminnmea/garminnmea_family.hpp"
#include "framing/nmea_format.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

std::optional<Identification> probe_garminnmea(const ProbeContext& line) {
  const framing::NmeaFormat format;
  const std::array<std::uint8_t, 2> empty_line{'\r', '\n'};
  line.link.write_all(empty_line, line.first_reply);
  links::FramedReader reader(line.link, format, 128);
  std::set<std::string> addresses;
  const auto note = [&addresses](std::span<const std::uint8_t> sentence) {
    const std::string_view body = framing::nmea_body(sentence);
    addresses.emplace(body.substr(0, body.find(',')));
  };
  // A receiver keeps the line busy: a line silent until the first reply's
  // deadline has none (and costs other families' probes no more time);
  // bytes that are not yet a sentence get the whole exchange's time.
  for (int good = 0; good < 2; ++good) {
    auto sentence = reader.next(good == 0 ? line.first_reply : line.finish);
    if (!sentence && good == 0 && reader.buffered() > 0) sentence = reader.next(line.finish);
    if (!sentence) return std::nullopt;
    note(*sentence);
  }
  // The rest of the burst names the receiver (Garmin's own PGRM sentences).
  for (int more = 0; more < 16; ++more) {
    const auto sentence = reader.next(std::min(line.finish, links::deadline_in(std::chrono::milliseconds(300))));
    if (!sentence) break;
    note(*sentence);
  }
  std::string heard;
  bool garmin = false;
  for (const auto& address : addresses) {
    heard += (heard.empty() ? "" : ", ") + address;
    garmin |= address.starts_with("PGRM");
  }
  Identification found{
      .driver = "garminnmea",
      .model = std::string(garmin ? "Garmin" : "NMEA 0183") + " GPS receiver (" + heard + ")",
      .interface_name = "gps",
      .config_driver = "garminnmea",
      .note = "add dgps_enable 0 unless RTCM corrections come on UDP",
  };
  if (line.baud != 0 && line.baud != 4800) {
    found.note = "the receiver runs at " + std::to_string(line.baud) + " baud: add baud " +
                 std::to_string(line.baud) + " to the section; " + found.note;
  }
  return found;
}

}  // namespace playerkit::families
