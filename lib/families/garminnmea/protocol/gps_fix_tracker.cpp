#include "families/garminnmea/protocol/gps_fix_tracker.hpp"

#include <cmath>

namespace playerkit::hardware::garminnmea {

namespace {

constexpr double kDay = 86400.0;
constexpr double kHalfDay = 43200.0;

}  // namespace

std::int64_t days_since_epoch(const Date& date) {
  // H. Hinnant's days_from_civil.
  const std::int64_t y = date.year - (date.month <= 2 ? 1 : 0);
  const std::int64_t era = (y >= 0 ? y : y - 399) / 400;
  const std::int64_t year_of_era = y - era * 400;
  const std::int64_t day_of_year = (153 * (date.month + (date.month > 2 ? -3 : 9)) + 2) / 5 + date.day - 1;
  const std::int64_t day_of_era = year_of_era * 365 + year_of_era / 4 - year_of_era / 100 + day_of_year;
  return era * 146097 + day_of_era - 719468;
}

Date date_from_days(std::int64_t days) {
  // H. Hinnant's civil_from_days.
  const std::int64_t z = days + 719468;
  const std::int64_t era = (z >= 0 ? z : z - 146096) / 146097;
  const std::int64_t day_of_era = z - era * 146097;
  const std::int64_t year_of_era = (day_of_era - day_of_era / 1460 + day_of_era / 36524 - day_of_era / 146096) / 365;
  const std::int64_t day_of_year = day_of_era - (365 * year_of_era + year_of_era / 4 - year_of_era / 100);
  const std::int64_t mp = (5 * day_of_year + 2) / 153;
  const int day = static_cast<int>(day_of_year - (153 * mp + 2) / 5 + 1);
  const int month = static_cast<int>(mp < 10 ? mp + 3 : mp - 9);
  return {static_cast<int>(year_of_era + era * 400 + (month <= 2 ? 1 : 0)), month, day};
}

std::optional<GpsFix> GpsFixTracker::take(std::string_view body) {
  const auto sentence = parse_sentence(body);
  if (!sentence) {
    ++ignored_;
    return std::nullopt;
  }
  return take(*sentence);
}

std::optional<GpsFix> GpsFixTracker::take(const Sentence& sentence) {
  ++used_;
  return std::visit([this](const auto& s) { return on(s); }, sentence);
}

void GpsFixTracker::enter_cycle(TimeOfDay time) {
  if (cycle_time_ && *cycle_time_ == time) return;
  cycle_time_ = time;
  cycle_has_gga_ = false;
}

void GpsFixTracker::stamp(GpsFix& fix, std::optional<TimeOfDay> time) const {
  if (!time) return;  // a sentence without its time: the cycle's
  double seconds = *time;
  fix.has_date = date_.has_value();
  std::int64_t day = 0;
  if (date_) {
    day = days_since_epoch(*date_);
    // The date is the RMC's; a time of day far from that RMC's is across midnight.
    if (date_time_ && seconds - *date_time_ > kHalfDay) --day;
    if (date_time_ && *date_time_ - seconds > kHalfDay) ++day;
  }
  const double whole = std::floor(seconds);
  fix.time_sec = day * static_cast<std::int64_t>(kDay) + static_cast<std::int64_t>(whole);
  fix.time_usec = static_cast<std::uint32_t>(std::lround((seconds - whole) * 1e6) % 1000000);
}

GpsFix GpsFixTracker::fix_at(std::optional<TimeOfDay> time, const Position& position) {
  if (time) enter_cycle(*time);
  GpsFix fix = last_;
  stamp(fix, time ? time : cycle_time_);
  fix.has_position = true;
  fix.latitude = position.latitude;
  fix.longitude = position.longitude;
  // A fix the receiver vouches for without a GGA this cycle: the last
  // GGA's quality if it had a fix, else a plain GPS fix.
  if (!cycle_has_gga_) fix.quality = quality_ > 0 ? quality_ : 1;
  return fix;
}

std::optional<GpsFix> GpsFixTracker::on(const Gga& gga) {
  if (gga.time) enter_cycle(*gga.time);
  cycle_has_gga_ = true;
  heard_gga_ = true;
  quality_ = gga.quality;
  if (gga.satellites) last_.satellites = *gga.satellites;
  if (gga.hdop) last_.hdop = *gga.hdop;
  if (gga.altitude) {
    last_.altitude = *gga.altitude;
    heard_gga_altitude_ = true;
  }
  if (gga.quality <= 0 || !gga.position) {
    // The receiver has no fix: said once, with no position.
    GpsFix none = last_;
    stamp(none, gga.time ? gga.time : cycle_time_);
    none.has_position = false;
    none.latitude = none.longitude = 0;
    none.quality = 0;
    last_.has_position = false;
    return none;
  }
  last_ = fix_at(gga.time, *gga.position);
  last_.quality = gga.quality;
  return last_;
}

std::optional<GpsFix> GpsFixTracker::on(const Rmc& rmc) {
  if (rmc.date && rmc.time) {
    date_ = rmc.date;
    date_time_ = rmc.time;
  }
  if (!rmc.valid || !rmc.position) return std::nullopt;
  last_ = fix_at(rmc.time, *rmc.position);
  return last_;
}

std::optional<GpsFix> GpsFixTracker::on(const Gll& gll) {
  if (!gll.valid || !gll.position) return std::nullopt;
  last_ = fix_at(gll.time, *gll.position);
  return last_;
}

std::optional<GpsFix> GpsFixTracker::on(const Gsa& gsa) {
  if (gsa.hdop && !heard_gga_) last_.hdop = *gsa.hdop;
  return std::nullopt;
}

std::optional<GpsFix> GpsFixTracker::on(const Gsv& gsv) {
  // Satellites in view stand in for those used only from a receiver that never says the latter (GGA).
  if (gsv.satellites_in_view && !heard_gga_) last_.satellites = *gsv.satellites_in_view;
  return std::nullopt;
}

std::optional<GpsFix> GpsFixTracker::on(const Pgrme& pgrme) {
  if (pgrme.horizontal) last_.horizontal_error = *pgrme.horizontal;
  if (pgrme.vertical) last_.vertical_error = *pgrme.vertical;
  return std::nullopt;
}

std::optional<GpsFix> GpsFixTracker::on(const Pgrmz& pgrmz) {
  // Whole feet: GGA's decimetres win whenever the receiver sends them.
  if (pgrmz.altitude && pgrmz.fix_dimension == 3 && !heard_gga_altitude_) last_.altitude = *pgrmz.altitude;
  return std::nullopt;
}

std::optional<GpsFix> GpsFixTracker::on(const Pgrmm& pgrmm) {
  datum_ = pgrmm.datum;
  return std::nullopt;
}

}  // namespace playerkit::hardware::garminnmea
