// The sentences of garminnmea.md §1-§2 and of the NMEA 0183 sentences 1.5
// ignored, golden text in, fields out; empty fields unknown.

#include "families/garminnmea/protocol/nmea_sentences.hpp"

#include <gtest/gtest.h>

#include "framing/nmea_format.hpp"

namespace playerkit::hardware::garminnmea {
namespace nmea_sentences_test {

template <typename T>
T as(std::string_view body) {
  const auto sentence = parse_sentence(body);
  EXPECT_TRUE(sentence) << body;
  EXPECT_TRUE(sentence && std::holds_alternative<T>(*sentence)) << body;
  return sentence && std::holds_alternative<T>(*sentence) ? std::get<T>(*sentence) : T{};
}

TEST(NmeaSentences, TheSheetsWorkedChecksums) {
  EXPECT_EQ(framing::nmea_checksum("GPGGA,123519,3401.2345,N,11817.1234,W,1,08,0.9,545.4,M,-33.9,M,,"), 0x74);
  EXPECT_EQ(framing::nmea_checksum("GPRMC,123519,A,3401.2345,N,11817.1234,W,000.0,360.0,150604,013.2,E"), 0x66);
  EXPECT_EQ(framing::nmea_checksum("PGRME,15.0,M,22.5,M,27.0,M"), 0x1A);
}

TEST(NmeaSentences, ReadsTheSheetsGga) {
  const Gga gga = as<Gga>("GPGGA,123519,3401.2345,N,11817.1234,W,1,08,0.9,545.4,M,-33.9,M,,");
  EXPECT_DOUBLE_EQ(*gga.time, 12 * 3600 + 35 * 60 + 19);
  ASSERT_TRUE(gga.position);
  EXPECT_NEAR(gga.position->latitude, 34.020575, 1e-9);
  EXPECT_NEAR(gga.position->longitude, -118.28539, 1e-9);
  EXPECT_EQ(gga.quality, 1);
  EXPECT_EQ(*gga.satellites, 8);
  EXPECT_DOUBLE_EQ(*gga.hdop, 0.9);
  EXPECT_DOUBLE_EQ(*gga.altitude, 545.4);
}

TEST(NmeaSentences, ReadsRmcGllAndGarminsOwn) {
  const Rmc rmc = as<Rmc>("GPRMC,123519,A,3401.2345,N,11817.1234,W,000.0,360.0,150604,013.2,E");
  EXPECT_TRUE(rmc.valid);
  EXPECT_EQ(*rmc.date, (Date{2004, 6, 15}));
  EXPECT_NEAR(rmc.position->latitude, 34.020575, 1e-9);
  const Gll gll = as<Gll>("GPGLL,4527.458,S,16709.165,E,225309,A");
  EXPECT_TRUE(gll.valid);
  EXPECT_DOUBLE_EQ(*gll.time, 22 * 3600 + 53 * 60 + 9);
  EXPECT_NEAR(gll.position->latitude, -45.4576333333, 1e-9);
  EXPECT_NEAR(gll.position->longitude, 167.15275, 1e-9);
  const Pgrme e = as<Pgrme>("PGRME,15.0,M,22.5,M,27.0,M");
  EXPECT_DOUBLE_EQ(*e.horizontal, 15.0);
  EXPECT_DOUBLE_EQ(*e.vertical, 22.5);
  const Pgrmz z = as<Pgrmz>("PGRMZ,125,f,3");
  EXPECT_NEAR(*z.altitude, 38.1, 1e-9);  // feet
  EXPECT_EQ(z.fix_dimension, 3);
  EXPECT_EQ(as<Pgrmm>("PGRMM,WGS 84").datum, "WGS 84");
  const Gsa gsa = as<Gsa>("GPGSA,A,3,03,,11,14,,,25,31,,,,,3.3,1.8,2.8");
  EXPECT_EQ(gsa.fix_dimension, 3);
  EXPECT_DOUBLE_EQ(*gsa.hdop, 1.8);
  EXPECT_EQ(*as<Gsv>("GPGSV,3,1,11,01,78,221,47,03,09,042,00,04,05,242,00,06,04,149,00").satellites_in_view, 11);
  // Other talkers say the same.
  EXPECT_EQ(as<Gga>("GNGGA,123519,3401.2345,N,11817.1234,W,2,08,0.9,545.4,M,-33.9,M,,").quality, 2);
}

TEST(NmeaSentences, AnEmptyFieldIsUnknownNotZeroOrStale) {
  const Gga gga = as<Gga>("GPGGA,123519,,,,,0,00,,,M,,M,,");
  EXPECT_FALSE(gga.position);  // 1.5 read minutes from the time field's leftovers
  EXPECT_EQ(gga.quality, 0);
  EXPECT_FALSE(gga.hdop);
  EXPECT_FALSE(gga.altitude);
  EXPECT_FALSE(as<Rmc>("GPRMC,123519,V,,,,,,,150604,,").valid);
  EXPECT_FALSE(as<Gll>("GPGLL,4527.458,S,16709.165,E,225309,A,N").valid);  // NMEA 2.3 mode N
  EXPECT_FALSE(as<Pgrme>("PGRME,,M,,M,,M").horizontal);
  // A receiver that stops early leaves the rest unknown.
  EXPECT_FALSE(as<Gga>("GPGGA,123519,3401.2345,N,11817.1234,W,1").satellites);
}

TEST(NmeaSentences, RefusesFieldsOutOfRange) {
  EXPECT_FALSE(parse_angle("9512.0", "N", 90));
  EXPECT_FALSE(parse_angle("3461.0", "N", 90));  // 61 minutes
  EXPECT_FALSE(parse_angle("3401.2", "E", 90));
  EXPECT_FALSE(parse_angle("34O1.2", "N", 90));
  EXPECT_FALSE(parse_time("246000"));
  EXPECT_FALSE(parse_date("320104"));
  EXPECT_EQ(parse_date("010199")->year, 1999);
  EXPECT_FALSE(parse_sentence("GPRMB,A,,,,,,,,,,,,V"));
  EXPECT_FALSE(parse_sentence("PGRMX,1"));
}

TEST(NmeaSentences, FormatsWhatItReads) {
  EXPECT_EQ(format_angle(34.020575, false, 4), "3401.2345");
  EXPECT_EQ(format_angle(-118.28539, true, 4), "11817.1234");
  EXPECT_EQ(format_angle(5.5, true, 3), "00530.000");
  EXPECT_EQ(format_angle(1.9999999999, false, 4), "0200.0000");  // minutes carried into degrees
  EXPECT_EQ(format_time(12 * 3600 + 35 * 60 + 19.25, 2), "123519.25");
  EXPECT_EQ(format_time(59.0, 0), "000059");
  EXPECT_EQ(format_date({2004, 6, 15}), "150604");
  for (const double degrees : {-89.123456789, -0.000001, 0.0, 12.5, 45.999999999}) {
    EXPECT_NEAR(*parse_angle(format_angle(degrees, false, 7), degrees < 0 ? "S" : "N", 90), degrees, 1e-9);
  }
}

}  // namespace nmea_sentences_test
}  // namespace playerkit::hardware::garminnmea
