#pragma once
// The sentences a Garmin receiver sends (garminnmea.md §2, and the NMEA 0183
// fields of the sentences 1.5 ignored), read from a sentence's body as
// framing::nmea_body() gives it. Every field is optional: an empty field is
// unknown, never zero, as gpsd reads them (an empty latitude is no fix).
// Any talker is accepted for the standard sentences (GP, GN, GL, ...).

#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace playerkit::hardware::garminnmea {

// "hhmmss[.sss]" as seconds since midnight, UTC.
using TimeOfDay = double;

struct Date {
  int year = 0;  // four digits
  int month = 0;
  int day = 0;
  friend bool operator==(const Date&, const Date&) = default;
};

struct Position {
  double latitude = 0;   // degrees, north positive
  double longitude = 0;  // degrees, east positive
};

struct Gga {
  std::optional<TimeOfDay> time;
  std::optional<Position> position;
  int quality = 0;  // 0 no fix, 1 GPS, 2 DGPS, ... (empty: 0)
  std::optional<int> satellites;
  std::optional<double> hdop;
  std::optional<double> altitude;  // metres above mean sea level
};

struct Rmc {
  std::optional<TimeOfDay> time;
  bool valid = false;  // status A (and mode indicator, when present, not N)
  std::optional<Position> position;
  std::optional<Date> date;
};

struct Gll {
  std::optional<TimeOfDay> time;
  bool valid = false;  // status A (and mode indicator, when present, not N)
  std::optional<Position> position;
};

struct Gsa {
  int fix_dimension = 0;  // 1 none, 2, 3; 0 unknown
  std::optional<double> hdop;
};

struct Gsv {
  std::optional<int> satellites_in_view;
};

// Garmin's estimated position errors.
struct Pgrme {
  std::optional<double> horizontal;  // metres
  std::optional<double> vertical;    // metres
};

// Garmin's altitude: in feet (`f`) or metres (`m`), and the fix's dimension.
struct Pgrmz {
  std::optional<double> altitude;  // metres
  int fix_dimension = 0;
};

// Garmin's map datum name.
struct Pgrmm {
  std::string datum;
};

using Sentence = std::variant<Gga, Rmc, Gll, Gsa, Gsv, Pgrme, Pgrmz, Pgrmm>;

// The sentence a body holds, or nullopt for one this family does not read
// (GPRMB, GPBOD, GPRTE, ...) or whose fields are malformed (a latitude of
// 95 degrees, minutes of 61, letters in a number).
[[nodiscard]] std::optional<Sentence> parse_sentence(std::string_view body);

// The comma-separated fields of a body; field 0 is the address ("GPGGA").
[[nodiscard]] std::vector<std::string_view> split_fields(std::string_view body);

// "4527.458","S" -> -45.4576...; nullopt when either is empty or out of range.
[[nodiscard]] std::optional<double> parse_angle(std::string_view value, std::string_view hemisphere, double limit);
[[nodiscard]] std::optional<TimeOfDay> parse_time(std::string_view value);
// "ddmmyy"; a two-digit year below 80 is 20yy, else 19yy (gpsd's guess).
[[nodiscard]] std::optional<Date> parse_date(std::string_view value);

// Composing (the emulator's side): "3401.234567" with `decimals` decimals
// of minutes, 2 degree digits for a latitude, 3 for a longitude.
[[nodiscard]] std::string format_angle(double degrees, bool longitude, int decimals);
[[nodiscard]] std::string format_time(TimeOfDay seconds, int decimals);
[[nodiscard]] std::string format_date(const Date& date);

}  // namespace playerkit::hardware::garminnmea
