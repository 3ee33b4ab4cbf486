#include "families/garminnmea/protocol/nmea_sentences.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>

namespace playerkit::hardware::garminnmea {

namespace {

std::optional<double> number_field(std::string_view text) {
  if (text.empty()) return std::nullopt;
  double value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<int> integer_field(std::string_view text) {
  if (text.empty()) return std::nullopt;
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// Field `index`, or "" past the end: a receiver that stops early left the rest unknown.
std::string_view field(const std::vector<std::string_view>& fields, std::size_t index) {
  return index < fields.size() ? fields[index] : std::string_view{};
}

std::optional<Position> position_at(const std::vector<std::string_view>& fields, std::size_t first) {
  const auto latitude = parse_angle(field(fields, first), field(fields, first + 1), 90);
  const auto longitude = parse_angle(field(fields, first + 2), field(fields, first + 3), 180);
  if (!latitude || !longitude) return std::nullopt;
  return Position{*latitude, *longitude};
}

// NMEA 2.3's mode indicator: N says the data are not valid whatever the status says.
bool status_valid(std::string_view status, std::string_view mode) { return status == "A" && mode != "N"; }

}  // namespace

std::vector<std::string_view> split_fields(std::string_view body) {
  std::vector<std::string_view> fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = body.find(',', start);
    fields.push_back(body.substr(start, comma == std::string_view::npos ? std::string_view::npos : comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

std::optional<double> parse_angle(std::string_view value, std::string_view hemisphere, double limit) {
  const auto raw = number_field(value);
  if (!raw || *raw < 0 || hemisphere.size() != 1) return std::nullopt;
  const double degrees = std::floor(*raw / 100.0);
  const double minutes = *raw - degrees * 100.0;
  if (minutes >= 60.0) return std::nullopt;
  const double angle = degrees + minutes / 60.0;
  if (angle > limit) return std::nullopt;
  const char side = hemisphere[0];
  if (limit == 90 && side != 'N' && side != 'S') return std::nullopt;
  if (limit == 180 && side != 'E' && side != 'W') return std::nullopt;
  return side == 'S' || side == 'W' ? -angle : angle;
}

std::optional<TimeOfDay> parse_time(std::string_view value) {
  if (value.size() < 6) return std::nullopt;
  const auto hours = integer_field(value.substr(0, 2));
  const auto minutes = integer_field(value.substr(2, 2));
  const auto seconds = number_field(value.substr(4));
  if (!hours || !minutes || !seconds || *hours > 23 || *minutes > 59 || *seconds < 0 || *seconds >= 61) {
    return std::nullopt;
  }
  return *hours * 3600.0 + *minutes * 60.0 + *seconds;
}

std::optional<Date> parse_date(std::string_view value) {
  if (value.size() != 6) return std::nullopt;
  const auto day = integer_field(value.substr(0, 2));
  const auto month = integer_field(value.substr(2, 2));
  const auto year = integer_field(value.substr(4, 2));
  if (!day || !month || !year || *day < 1 || *day > 31 || *month < 1 || *month > 12 || *year < 0) return std::nullopt;
  return Date{*year < 80 ? 2000 + *year : 1900 + *year, *month, *day};
}

std::optional<Sentence> parse_sentence(std::string_view body) {
  const auto fields = split_fields(body);
  const std::string_view address = fields[0];
  if (address.size() == 5 && address.substr(0, 4) == "PGRM") {
    switch (address[4]) {
      case 'E':
        return Pgrme{.horizontal = field(fields, 2) == "M" ? number_field(field(fields, 1)) : std::nullopt,
                     .vertical = field(fields, 4) == "M" ? number_field(field(fields, 3)) : std::nullopt};
      case 'Z': {
        const auto altitude = number_field(field(fields, 1));
        const std::string_view unit = field(fields, 2);
        Pgrmz z{.altitude = std::nullopt, .fix_dimension = integer_field(field(fields, 3)).value_or(0)};
        if (altitude && unit == "f") z.altitude = *altitude * 0.3048;
        if (altitude && unit == "m") z.altitude = *altitude;
        return z;
      }
      case 'M':
        return Pgrmm{std::string(field(fields, 1))};
      default:
        return std::nullopt;
    }
  }
  if (address.size() != 5) return std::nullopt;
  const std::string_view type = address.substr(2);
  if (type == "GGA") {
    Gga gga{.time = parse_time(field(fields, 1)),
            .position = position_at(fields, 2),
            .quality = integer_field(field(fields, 6)).value_or(0),
            .satellites = integer_field(field(fields, 7)),
            .hdop = number_field(field(fields, 8)),
            .altitude = std::nullopt};
    if (field(fields, 10) == "M" || field(fields, 10).empty()) gga.altitude = number_field(field(fields, 9));
    return gga;
  }
  if (type == "RMC") {
    return Rmc{.time = parse_time(field(fields, 1)),
               .valid = status_valid(field(fields, 2), field(fields, 12)),
               .position = position_at(fields, 3),
               .date = parse_date(field(fields, 9))};
  }
  if (type == "GLL") {
    return Gll{.time = parse_time(field(fields, 5)),
               .valid = status_valid(field(fields, 6), field(fields, 7)),
               .position = position_at(fields, 1)};
  }
  if (type == "GSA") {
    return Gsa{.fix_dimension = integer_field(field(fields, 2)).value_or(0), .hdop = number_field(field(fields, 16))};
  }
  if (type == "GSV") return Gsv{.satellites_in_view = integer_field(field(fields, 3))};
  return std::nullopt;
}

std::string format_angle(double degrees, bool longitude, int decimals) {
  const double magnitude = std::fabs(degrees);
  // Rounded in minutes first, so that 59.99999 minutes carry into the degrees.
  const double scale = std::pow(10.0, decimals);
  const double total_minutes = std::round(magnitude * 60.0 * scale) / scale;
  const int whole_degrees = static_cast<int>(std::floor(total_minutes / 60.0 + 1e-12));
  const double minutes = std::max(0.0, total_minutes - whole_degrees * 60.0);
  char text[40];
  std::snprintf(text, sizeof text, longitude ? "%03d%0*.*f" : "%02d%0*.*f", whole_degrees,
                decimals > 0 ? decimals + 3 : 2, decimals, minutes);
  return text;
}

std::string format_time(TimeOfDay seconds, int decimals) {
  const double scale = std::pow(10.0, decimals);
  const double rounded = std::fmod(std::round(seconds * scale) / scale, 86400.0);
  const int whole = static_cast<int>(std::floor(rounded + 1e-9));
  char text[32];
  std::snprintf(text, sizeof text, "%02d%02d%0*.*f", whole / 3600, (whole / 60) % 60, decimals > 0 ? decimals + 3 : 2,
                decimals, rounded - (whole / 60) * 60.0);
  return text;
}

std::string format_date(const Date& date) {
  char text[16];
  std::snprintf(text, sizeof text, "%02d%02d%02d", date.day, date.month, date.year % 100);
  return text;
}

}  // namespace playerkit::hardware::garminnmea
