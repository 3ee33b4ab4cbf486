#include "framing/nmea_format.hpp"

#include <gtest/gtest.h>

#include "framing/test_support.hpp"

namespace playerkit::framing {
namespace nmea_format_test {

using namespace test_support;
using Kind = FrameScan::Kind;

// garminnmea.md §1, "Worked checksum examples".
constexpr std::string_view kSheetGga = "$GPGGA,123519,3401.2345,N,11817.1234,W,1,08,0.9,545.4,M,-33.9,M,,*74\r\n";
constexpr std::string_view kSheetRmc =
    "$GPRMC,123519,A,3401.2345,N,11817.1234,W,000.0,360.0,150604,013.2,E*66\r\n";
constexpr std::string_view kSheetPgrme = "$PGRME,15.0,M,22.5,M,27.0,M*1A\r\n";

// Real sentences from a Garmin 48, copied from
// /work/shared/data/gpsd-garmin/garmin48.log (gpsd's regression tests,
// Copyright (c) 2010 by the GPSD project, BSD terms apply), with the CR LF
// the receiver sent.
constexpr std::string_view kGarmin48[] = {
    "$GPRMC,225308,A,4527.458,S,16709.165,E,000.0,094.5,060601,024.1,E*6D\r\n",
    "$GPRMB,A,,,,,,,,,,,,V*71\r\n",
    "$GPGGA,225308,4527.458,S,16709.165,E,1,05,2.1,14.7,M,1.1,M,,*53\r\n",
    "$GPGSV,3,1,11,01,78,221,47,03,09,042,00,04,05,242,00,06,04,149,00*70\r\n",
    "$PGRMM,WGS 84*06\r\n",
};

TEST(NmeaFormat, TheSheetsWorkedExamplesAreWholeSentences) {
  const NmeaFormat format;
  for (const std::string_view sentence : {kSheetGga, kSheetRmc, kSheetPgrme}) {
    const auto bytes = text_bytes(sentence);
    const FrameScan scan = format.scan(bytes);
    EXPECT_EQ(scan.kind, Kind::frame) << sentence;
    EXPECT_EQ(scan.length, bytes.size()) << sentence;
  }
  EXPECT_EQ(nmea_checksum("PGRME,15.0,M,22.5,M,27.0,M"), 0x1a);
  EXPECT_EQ(nmea_body(text_bytes(kSheetPgrme)), "PGRME,15.0,M,22.5,M,27.0,M");
}

TEST(NmeaFormat, RealGarminSentencesComeOutOneByOneFromAnyCut) {
  const NmeaFormat format;
  Bytes stream;
  for (const std::string_view sentence : kGarmin48) stream = concat({stream, text_bytes(sentence)});
  for (const std::size_t piece : {std::size_t{1}, std::size_t{5}, std::size_t{64}, stream.size()}) {
    const Cut result = cut(format, stream, piece);
    ASSERT_EQ(result.frames.size(), std::size(kGarmin48)) << piece;
    for (std::size_t i = 0; i < result.frames.size(); ++i) EXPECT_EQ(result.frames[i], text_bytes(kGarmin48[i]));
    EXPECT_EQ(result.skipped, 0u);
    EXPECT_EQ(result.left_over, 0u);
  }
}

TEST(NmeaFormat, ABareLfEndsASentenceToo) {
  // As the sentences are stored in garmin38.log (same provenance as above).
  const NmeaFormat format;
  const auto bytes = text_bytes("$PGRMZ,125,f,3*1D\n$PGRMM,NAD83*29\n");
  const Cut result = cut(format, bytes);
  ASSERT_EQ(result.frames.size(), 2u);
  EXPECT_EQ(nmea_body(result.frames[0]), "PGRMZ,125,f,3");
  EXPECT_EQ(nmea_body(result.frames[1]), "PGRMM,NAD83");
}

TEST(NmeaFormat, ABadChecksumIsReportedWhole) {
  const NmeaFormat format;
  // The sheet's RMC with its last checksum digit changed.
  std::string damaged(kSheetRmc);
  damaged[damaged.size() - 3] = '7';
  const auto bytes = text_bytes(damaged);
  EXPECT_EQ(format.scan(bytes).kind, Kind::bad_checksum);
  EXPECT_EQ(format.scan(bytes).length, bytes.size());
  // Lower-case hex digits are as good as upper-case ones.
  EXPECT_EQ(format.scan(text_bytes("$PGRME,15.0,M,22.5,M,27.0,M*1a\r\n")).kind, Kind::frame);
  // A damaged checksum field.
  for (const std::string_view broken : {"$PGRME,15.0,M,22.5,M,27.0,M*1\r\n", "$PGRME,15.0,M,22.5,M,27.0,M*1G\r\n",
                                        "$PGRME,15.0,M,22.5,M,27.0,M*1A0\r\n"}) {
    EXPECT_EQ(format.scan(text_bytes(broken)).kind, Kind::bad_checksum) << broken;
  }
}

TEST(NmeaFormat, ASentenceWithoutChecksumIsAcceptedOnlyWhenAllowed) {
  const auto bytes = text_bytes("$GPRMB,A,,,,,,,,,,,,V\r\n");
  EXPECT_EQ(NmeaFormat().scan(bytes).kind, Kind::bad_checksum);
  const NmeaFormat lenient({.accept_missing_checksum = true});
  EXPECT_EQ(lenient.scan(bytes).kind, Kind::frame);
  EXPECT_EQ(lenient.scan(bytes).length, bytes.size());
  EXPECT_EQ(nmea_body(bytes), "GPRMB,A,,,,,,,,,,,,V");
}

TEST(NmeaFormat, NoiseBeforeASentenceIsSkippedUpToItsStart) {
  const NmeaFormat format;
  const auto stream = concat({hex("00 FF 13 0D 0A"), text_bytes("GPGGA,12,"), text_bytes(kSheetPgrme)});
  const Cut result = cut(format, stream, 3);
  ASSERT_EQ(result.frames.size(), 1u);
  EXPECT_EQ(result.frames[0], text_bytes(kSheetPgrme));
  EXPECT_EQ(result.skipped, 14u);
}

TEST(NmeaFormat, ASentenceCutShortGivesWayToTheNextStart) {
  const NmeaFormat format;
  // The first sentence lost its end (a dropped stretch of bytes); the second is whole.
  const auto stream = concat({text_bytes("$GPGGA,123519,3401.2"), text_bytes(kSheetPgrme)});
  const Cut result = cut(format, stream);
  ASSERT_EQ(result.frames.size(), 1u);
  EXPECT_EQ(result.frames[0], text_bytes(kSheetPgrme));
  EXPECT_EQ(result.skipped, 20u);
  // `!` starts sentences too (AIS encapsulation).
  const auto ais = nmea_sentence("AIVDM,1,1,,A,15M67N0000G?Uf6E`FepT@3n00Sa,0", '!');
  EXPECT_EQ(format.scan(ais).kind, Kind::frame);
  EXPECT_EQ(ais.front(), '!');
}

TEST(NmeaFormat, BytesThatAreNotTextEndTheSentence) {
  const NmeaFormat format;
  // At the wrong baud rate a `$` may appear among bytes that are no text.
  const auto stream = concat({text_bytes("$GP"), hex("C3 9A"), text_bytes("GA*00\r\n"), text_bytes(kSheetPgrme)});
  const Cut result = cut(format, stream);
  ASSERT_EQ(result.frames.size(), 1u);
  EXPECT_EQ(result.frames[0], text_bytes(kSheetPgrme));
  EXPECT_TRUE(result.bad_checksums.empty());
  // A CR inside a sentence is no line end.
  EXPECT_EQ(format.scan(text_bytes("$GP\rGGA*00\r\n")).kind, Kind::skip);
}

TEST(NmeaFormat, AnEndlessSentenceIsDroppedAtTheLongestLength) {
  const NmeaFormat format({.max_length = 90});
  std::string endless = "$GPGSV";
  endless.append(500, ',');
  const Cut result = cut(format, concat({text_bytes(endless), text_bytes(kSheetGga)}), 7);
  ASSERT_EQ(result.frames.size(), 1u);
  EXPECT_EQ(result.frames[0], text_bytes(kSheetGga));
  EXPECT_EQ(result.left_over, 0u);
  // Without a start in sight, nothing is kept waiting at all.
  EXPECT_EQ(cut(format, text_bytes(std::string(300, ','))).left_over, 0u);
  // The default leaves room beyond the standard's 82 characters.
  std::string long_body = "PGRMX,";
  long_body.append(100, '1');
  EXPECT_EQ(NmeaFormat().scan(nmea_sentence(long_body)).kind, Kind::frame);
  EXPECT_EQ(format.scan(nmea_sentence(long_body)).kind, Kind::skip);
}

TEST(NmeaFormat, PartialSentencesWait) {
  const NmeaFormat format;
  EXPECT_EQ(format.scan({}).kind, Kind::need_more);
  EXPECT_EQ(format.scan(text_bytes("$GPGGA,1")).kind, Kind::need_more);
  const FrameScan at_cr = format.scan(text_bytes("$PGRMM,WGS 84*06\r"));
  EXPECT_EQ(at_cr.kind, Kind::need_more);
  EXPECT_EQ(at_cr.length, 18u);
}

TEST(NmeaFormat, EncodedSentencesRoundTrip) {
  const NmeaFormat format;
  for (const std::string_view body : {"GPGGA,123519,3401.2345,N,11817.1234,W,1,08,0.9,545.4,M,-33.9,M,,",
                                      "PGRME,15.0,M,22.5,M,27.0,M", ""}) {
    const auto sentence = nmea_sentence(body);
    const Cut result = cut(format, sentence);
    ASSERT_EQ(result.frames.size(), 1u) << body;
    EXPECT_EQ(nmea_body(result.frames[0]), body);
  }
  // The encoder writes what the sheet computed.
  EXPECT_EQ(nmea_sentence("GPGGA,123519,3401.2345,N,11817.1234,W,1,08,0.9,545.4,M,-33.9,M,,"), text_bytes(kSheetGga));
}

}  // namespace nmea_format_test
}  // namespace playerkit::framing
