#pragma once
// A receiver's sentences, in whatever order it sends them, made into fixes
// the way gpsd makes them: each sentence carrying a position the receiver
// vouches for (GGA quality above 0, RMC or GLL status A) is a fix at once,
// with its own time of day, so GLL's fix counts and a GGA before its RMC is
// not a cycle late. A sentence's time of day starts a new cycle; what the
// cycle's sentences do not say (a GLL has no altitude) is the last value
// heard. The date comes from the last RMC, moved across midnight when the
// time of day wraps, so a GGA before its RMC has the right date.
//
// Nothing else is filtered: 1.5's outlier filter dropped good fixes after
// every start (garminnmea.md §3).

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "families/garminnmea/protocol/nmea_sentences.hpp"

namespace playerkit::hardware::garminnmea {

struct GpsFix {
  // UTC seconds since 1970 (time of day alone, on 1970-01-01, before the
  // first RMC gave a date) and the fraction the receiver sent.
  std::int64_t time_sec = 0;
  std::uint32_t time_usec = 0;
  bool has_date = false;
  // False: the receiver said it has no fix (a GGA of quality 0); the
  // position fields are then 0.
  bool has_position = false;
  double latitude = 0;
  double longitude = 0;
  double altitude = 0;  // metres above mean sea level; 0 until one is heard
  int quality = 0;
  int satellites = 0;
  double hdop = 0;
  double horizontal_error = 0;  // metres (PGRME), 0 until heard
  double vertical_error = 0;
};

class GpsFixTracker {
 public:
  // One sentence's body; the fix it makes, if any.
  std::optional<GpsFix> take(std::string_view body);
  std::optional<GpsFix> take(const Sentence& sentence);

  [[nodiscard]] const std::optional<Date>& date() const { return date_; }
  [[nodiscard]] const std::string& datum() const { return datum_; }
  [[nodiscard]] std::uint64_t sentences_used() const { return used_; }
  [[nodiscard]] std::uint64_t sentences_ignored() const { return ignored_; }

 private:
  std::optional<GpsFix> on(const Gga& gga);
  std::optional<GpsFix> on(const Rmc& rmc);
  std::optional<GpsFix> on(const Gll& gll);
  std::optional<GpsFix> on(const Gsa& gsa);
  std::optional<GpsFix> on(const Gsv& gsv);
  std::optional<GpsFix> on(const Pgrme& pgrme);
  std::optional<GpsFix> on(const Pgrmz& pgrmz);
  std::optional<GpsFix> on(const Pgrmm& pgrmm);

  void enter_cycle(TimeOfDay time);
  GpsFix fix_at(std::optional<TimeOfDay> time, const Position& position);
  void stamp(GpsFix& fix, std::optional<TimeOfDay> time) const;

  std::optional<Date> date_;
  std::optional<TimeOfDay> date_time_;  // the time of day of the RMC that gave the date
  std::optional<TimeOfDay> cycle_time_;
  bool cycle_has_gga_ = false;
  int quality_ = 0;  // the last GGA's
  bool heard_gga_ = false;
  bool heard_gga_altitude_ = false;
  GpsFix last_;
  std::string datum_;
  std::uint64_t used_ = 0;
  std::uint64_t ignored_ = 0;
};

// Days since 1970-01-01 of a civil date (proleptic Gregorian).
[[nodiscard]] std::int64_t days_since_epoch(const Date& date);
[[nodiscard]] Date date_from_days(std::int64_t days);

}  // namespace playerkit::hardware::garminnmea
