// NMEA from a byte stream: framing, recovery and counters (docs/nmea.md).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "drivers/gps/nmea_lexer.hpp"
#include "drivers/gps/nmea_stream.hpp"
#include "host_tests/support/nmea_text.hpp"

using sinu::drivers::GpsFix;
using sinu::drivers::NmeaLexer;
using sinu::drivers::NmeaStream;

namespace {

using sinu::test::nmea_with_checksum;
std::string with_checksum(const std::string& body) { return nmea_with_checksum(body); }

std::vector<std::string> frame(const std::string& bytes, NmeaLexer& lexer) {
  std::vector<std::string> out;
  for (char c : bytes)
    if (lexer.push(c)) out.emplace_back(lexer.sentence());
  if (lexer.finish()) out.emplace_back(lexer.sentence());
  return out;
}

const std::string kGga = with_checksum("GPGGA,101520.40,3024.51234,N,11421.12345,E,1,12,0.8,45.3,M,-2.1,M,,");
const std::string kRmc = with_checksum("GPRMC,101520.40,A,3024.51234,N,11421.12345,E,10.0,90.0,220326,,,A");

}  // namespace

TEST(NmeaLexer, FramesOnCrLfOrBareLfAndSkipsLineNoise) {
  NmeaLexer lexer;
  const auto s = frame("garbage\x01\xff" + kGga + "\r\n" + kRmc + "\nxx", lexer);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0], kGga);
  EXPECT_EQ(s[1], kRmc);
  EXPECT_EQ(lexer.counters().noise_bytes, 11u);  // "garbage" + 2 control bytes + "xx"
}

TEST(NmeaLexer, DollarDollarRestartsAndNulAbandons) {
  NmeaLexer lexer;
  const std::string bytes = "$$" + kGga.substr(1) + "\r\n" + kGga.substr(0, 20) + std::string(1, '\0') + "\r\n" + kRmc + "\r\n";
  const auto s = frame(bytes, lexer);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0], kGga);
  EXPECT_EQ(s[1], kRmc);
  EXPECT_EQ(lexer.counters().interrupted, 1u);  // the NUL; "$$" is a plain restart
}

TEST(NmeaLexer, SplicedSentenceIsResumedIfItsLineContinuesElseDropped) {
  // A receiver injects one sentence into another (gpsd's isync capture): the
  // rest of the interrupted one follows the intruder's CR LF.
  const std::string head = kGga.substr(0, 30) + kRmc + "\r\n";
  for (const bool continues : {true, false}) {
    SCOPED_TRACE(continues);
    NmeaLexer lexer;
    const auto s = frame(head + (continues ? kGga.substr(30) : kGga) + "\r\n", lexer);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_EQ(s[0], kRmc);
    EXPECT_EQ(s[1], kGga);
    EXPECT_EQ(lexer.counters().resumed, continues ? 1u : 0u);
    EXPECT_EQ(lexer.counters().interrupted, continues ? 0u : 1u);
  }
}

TEST(NmeaLexer, OverLongSentenceIsCountedAndTheNextOneSurvives) {
  NmeaLexer lexer;
  const std::string longer = "$GPTXT," + std::string(sinu::drivers::kNmeaMaxSentence, 'A') + "*00\r\n";
  const auto s = frame(longer + kGga + "\r\n", lexer);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(s[0], kGga);
  EXPECT_EQ(lexer.counters().too_long, 1u);
}

TEST(NmeaLexer, CommentLinesOnlyInCommentMode) {
  NmeaLexer gpsd_log(true), serial(false);
  const std::string bytes = "# Name: x $GPGGA,1*00\n" + kGga + "\n";
  EXPECT_EQ(frame(bytes, gpsd_log).size(), 1u);
  EXPECT_EQ(gpsd_log.counters().comment_lines, 1u);
  EXPECT_EQ(frame(bytes, serial).size(), 2u);  // on a serial line '#' is noise; the '$' starts a sentence
}

TEST(NmeaStream, CountsEveryMalformedCaseAndStillAssemblesTheFix) {
  std::string lower = kGga;  // lower-case hex is valid NMEA
  lower[lower.size() - 2] = static_cast<char>(std::tolower(lower[lower.size() - 2]));
  lower[lower.size() - 1] = static_cast<char>(std::tolower(lower[lower.size() - 1]));
  std::string bad = kRmc;
  bad[10] = '9';  // checksum now wrong
  const std::string bytes = bad + "\r\n" + kRmc.substr(0, kRmc.size() - 3) + "\r\n" +  // bad, missing checksum
                            with_checksum("GPGGA,1015xx.40,3024.5,N,11421.1,E,1,12,0.8,45.3,M,,M,,") + "\r\n" +  // malformed
                            with_checksum("GPGSV,1,1,00") + "\r\n" +  // unknown to us: ignored
                            lower + "\r\n" + kRmc + "\r\n";
  NmeaStream stream;
  GpsFix fix;
  std::vector<GpsFix> fixes;
  for (char c : bytes)
    if (stream.push(c, 12.5, fix)) fixes.push_back(fix);
  while (stream.finish(13.0, fix)) fixes.push_back(fix);
  const auto c = stream.counters();
  EXPECT_EQ(c.sentences.bad_checksum, 1u);
  EXPECT_EQ(c.sentences.missing_checksum, 1u);
  EXPECT_EQ(c.sentences.malformed_field, 1u);
  EXPECT_EQ(c.sentences.ignored, 1u);
  EXPECT_EQ(c.sentences.good, 2u);
  ASSERT_EQ(fixes.size(), 1u);
  EXPECT_TRUE(fixes[0].has_position());
  EXPECT_NEAR(*fixes[0].lat_deg, 30.0 + 24.51234 / 60.0, 1e-12);
  EXPECT_NEAR(*fixes[0].speed_m_s, 10.0 * 1852.0 / 3600.0, 1e-12);
  EXPECT_EQ(fixes[0].arrival_s, 12.5);
}

TEST(NmeaParser, DecodesGllAsAPositionSource) {
  NmeaStream stream;
  GpsFix fix;
  bool got = false;
  for (char c : with_checksum("GPGLL,4916.45,N,12311.12,W,225444,A,A") + "\r\n") got |= stream.push(c, 1.0, fix);
  got |= stream.finish(1.0, fix);
  ASSERT_TRUE(got);
  EXPECT_TRUE(fix.has_position());
  EXPECT_NEAR(*fix.lon_deg, -(123.0 + 11.12 / 60.0), 1e-12);
  EXPECT_EQ(fix.utc_ms, (22 * 3600 + 54 * 60 + 44) * 1000);
}
