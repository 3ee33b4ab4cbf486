// "Who are you?" on a line, NMEA style: a receiver never answers, it talks,
// so the probe only listens, and two sentences with good checksums are a
// receiver (one could be chance at the wrong speed). Nothing is sent.
#include <algorithm>
#include <chrono>
#include <set>
#include <string>

#include "families/garminnmea/garminnmea_family.hpp"
#include "framing/nmea_format.hpp"
#include "links/framed_reader.hpp"

namespace playerkit::families {

std::optional<Identification> probe_garminnmea(const ProbeContext& line) {
  const framing::NmeaFormat format;
  links::FramedReader reader(line.link, format, 128);
  std::set<std::string> addresses;
  const auto note = [&addresses](std::span<const std::uint8_t> sentence) {
    const std::string_view body = framing::nmea_body(sentence);
    addresses.emplace(body.substr(0, body.find(',')));
  };
  // A receiver sends once a second and may be between two bursts: listen
  // for the whole exchange's time, not only for a first reply's.
  for (int good = 0; good < 2; ++good) {
    const auto sentence = reader.next(line.finish);
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
