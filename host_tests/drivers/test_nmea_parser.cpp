// NMEA sentence framing, field decoding and epoch assembly.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "drivers/gps/fix_assembler.hpp"
#include "drivers/gps/nmea_parser.hpp"

using namespace sinu::drivers;

namespace {

/// Builds "$body*hh" with a correct checksum, computed independently here.
std::string with_checksum(const std::string& body, bool lower_case = false) {
  unsigned sum = 0;
  for (char c : body) sum ^= static_cast<unsigned char>(c);
  char hex[4];
  std::snprintf(hex, sizeof hex, lower_case ? "%02x" : "%02X", sum);
  return "$" + body + "*" + hex;
}

}  // namespace

TEST(NmeaSentence, ChecksumAcceptsEitherCaseAndRejectsMismatch) {
  // Checksum of a real u-blox sentence as published in the receiver manual.
  EXPECT_EQ(check_sentence("$GPGGA,092725.00,4717.11399,N,00833.91590,E,1,08,1.01,499.6,M,48.0,M,,*5B"),
            SentenceCheck::Ok);
  const std::string body = "GNRMC,193400.50,A,4005.7976080,N,10508.8468980,W,0.020,348.69,080725,,,R";
  EXPECT_EQ(check_sentence(with_checksum(body)), SentenceCheck::Ok);
  EXPECT_EQ(check_sentence(with_checksum(body, true)), SentenceCheck::Ok);
  std::string bad = with_checksum(body);
  bad[10] = '9';  // one corrupted digit
  EXPECT_EQ(check_sentence(bad), SentenceCheck::BadChecksum);
}

TEST(NmeaSentence, FramingErrors) {
  EXPECT_EQ(check_sentence("GPGGA,1*00"), SentenceCheck::NoDollar);
  EXPECT_EQ(check_sentence("$GPGGA,092725.00,4717.11399,N"), SentenceCheck::MissingChecksum);  // truncated
  EXPECT_EQ(check_sentence("$GPGGA,0927*5"), SentenceCheck::MissingChecksum);
  EXPECT_EQ(check_sentence(with_checksum("GPGGA,09\x01""27")), SentenceCheck::BadCharacter);
  EXPECT_EQ(check_sentence(with_checksum("gpgga,1")), SentenceCheck::BadAddress);
  EXPECT_EQ(check_sentence("$" + std::string(sinu::drivers::kNmeaMaxSentence, 'A') + "*00"), SentenceCheck::TooLong);
}

TEST(NmeaParser, DecodesGgaWithUnitsAndSigns) {
  NmeaParser p;
  NmeaMessage m;
  ASSERT_EQ(p.parse(with_checksum("GNGGA,193400.50,4005.7976080,N,10508.8468980,W,4,21,,1601.474,M,-21.387,M,,"), m),
            ParseResult::Message);
  const auto& g = std::get<GgaMessage>(m);
  EXPECT_EQ(*g.utc_ms, ((19 * 3600 + 34 * 60) + 0) * 1000 + 500);
  // ddmm.mmmm -> degrees: 40 + 5.7976080/60, west negative.
  EXPECT_NEAR(*g.lat_deg, 40.0 + 5.7976080 / 60.0, 1e-12);
  EXPECT_NEAR(*g.lon_deg, -(105.0 + 8.8468980 / 60.0), 1e-12);
  EXPECT_EQ(g.quality, 4);
  EXPECT_EQ(*g.sats, 21);
  EXPECT_FALSE(g.hdop.has_value()) << "an empty field is 'not available', never zero";
  EXPECT_DOUBLE_EQ(*g.alt_msl_m, 1601.474);
  EXPECT_DOUBLE_EQ(*g.geoid_sep_m, -21.387);
}

TEST(NmeaParser, DecodesRmcSpeedInMetresPerSecond) {
  NmeaParser p;
  NmeaMessage m;
  ASSERT_EQ(p.parse(with_checksum("GPRMC,101520.40,A,3024.51234,N,11421.12345,E,77.75,123.4,220326,,,A"), m),
            ParseResult::Message);
  const auto& r = std::get<RmcMessage>(m);
  EXPECT_TRUE(r.valid);
  EXPECT_NEAR(*r.speed_m_s, 77.75 * 1852.0 / 3600.0, 1e-12);  // knots -> m/s by definition of the knot
  EXPECT_DOUBLE_EQ(*r.course_deg, 123.4);
  EXPECT_EQ(*r.date, (UtcDate{2026, 3, 22}));
  EXPECT_EQ(r.mode, 'A');
}

TEST(NmeaParser, DecodesGstSigmas) {
  NmeaParser p;
  NmeaMessage m;
  ASSERT_EQ(p.parse(with_checksum("GPGST,101520.40,1.2,0.9,0.7,35.0,0.85,0.72,1.9"), m), ParseResult::Message);
  const auto& g = std::get<GstMessage>(m);
  EXPECT_DOUBLE_EQ(*g.sigma_lat_m, 0.85);
  EXPECT_DOUBLE_EQ(*g.sigma_lon_m, 0.72);
  EXPECT_DOUBLE_EQ(*g.sigma_alt_m, 1.9);
}

TEST(NmeaParser, CountsEveryKindOfBadSentence) {
  NmeaParser p;
  NmeaMessage m;
  EXPECT_EQ(p.parse(with_checksum("GPGGA,1015xx.40,3024.51234,N,11421.12345,E,1,8,1.0,45.3,M,0.0,M,,"), m),
            ParseResult::Corrupt);
  EXPECT_EQ(p.parse(with_checksum("GPGGA,101520.40,3024.51234,Q,11421.12345,E,1,8,1.0,45.3,M,0.0,M,,"), m),
            ParseResult::Corrupt);  // hemisphere 'Q'
  EXPECT_EQ(p.parse(with_checksum("GPGGA,101520.40,3024.5"), m), ParseResult::Corrupt);  // too few fields
  EXPECT_EQ(p.parse("$GPGGA,101520.40*00", m), ParseResult::Corrupt);
  EXPECT_EQ(p.parse("$GPGGA,101520.40", m), ParseResult::Corrupt);
  EXPECT_EQ(p.parse(with_checksum("GPGSV,3,1,11,03,03,111,00"), m), ParseResult::Ignored);
  EXPECT_EQ(p.parse(with_checksum("PUBX,00,1"), m), ParseResult::Ignored);
  const NmeaCounters& c = p.counters();
  EXPECT_EQ(c.malformed_field, 3u);
  EXPECT_EQ(c.bad_checksum, 1u);
  EXPECT_EQ(c.missing_checksum, 1u);
  EXPECT_EQ(c.ignored, 2u);
  EXPECT_EQ(c.good, 0u);
  EXPECT_EQ(c.total(), 7u);
}

TEST(FixAssembler, GroupsSentencesOfOneEpochAndLearnsTheCycleEnd) {
  NmeaParser p;
  FixAssembler a;
  NmeaMessage m;
  GpsFix fix;
  int emitted = 0;
  auto feed = [&](const std::string& body, double t) {
    ASSERT_EQ(p.parse(with_checksum(body), m), ParseResult::Message);
    if (a.add(m, t, fix)) ++emitted;
  };
  feed("GNGGA,120000.00,4000.0000,N,10500.0000,W,1,10,0.9,100.0,M,-20.0,M,,", 10.05);
  feed("GNRMC,120000.00,A,4000.0000,N,10500.0000,W,10.0,90.0,010126,,,A", 10.06);
  feed("GNGST,120000.00,1.0,,,,0.5,0.6,1.5", 10.07);
  EXPECT_EQ(emitted, 0) << "the first epoch ends only when the next one starts";
  feed("GNGGA,120000.20,4000.0010,N,10500.0000,W,1,10,0.9,100.0,M,-20.0,M,,", 10.25);
  ASSERT_EQ(emitted, 1);
  EXPECT_EQ(fix.utc_ms, 12 * 3600 * 1000);
  EXPECT_DOUBLE_EQ(fix.arrival_s, 10.05);
  EXPECT_TRUE(fix.has_position());
  EXPECT_DOUBLE_EQ(*fix.ellipsoid_height_m(), 80.0);
  EXPECT_NEAR(*fix.speed_m_s, 10.0 * 1852.0 / 3600.0, 1e-12);
  EXPECT_DOUBLE_EQ(*fix.sigma_lon_m, 0.6);
  feed("GNRMC,120000.20,A,4000.0010,N,10500.0000,W,10.0,90.0,010126,,,A", 10.26);
  feed("GNGST,120000.20,1.0,,,,0.5,0.6,1.5", 10.27);
  EXPECT_EQ(emitted, 2) << "GST ended the previous epoch, so it ends this one at once";
  EXPECT_EQ(fix.utc_ms, 12 * 3600 * 1000 + 200);
  EXPECT_FALSE(a.flush(fix)) << "nothing left open";
}

/// Feeds one GGA (+ RMC, + GST when `gst`) epoch at UTC 12:00:00 + k/5 s; returns the fixes emitted.
std::vector<GpsFix> feed_epoch(NmeaParser& p, FixAssembler& a, int k, bool gst) {
  std::vector<GpsFix> out;
  char utc[32];
  std::snprintf(utc, sizeof utc, "1200%02d.%02d", k / 5, (k % 5) * 20);
  const double t = 10.0 + 0.2 * k;
  NmeaMessage m;
  GpsFix fix;
  auto feed = [&](const std::string& body, double arrival) {
    EXPECT_EQ(p.parse(with_checksum(body), m), ParseResult::Message) << body;
    if (a.add(m, arrival, fix)) out.push_back(fix);
  };
  feed(std::string("GNGGA,") + utc + ",4000.0000,N,10500.0000,W,1,10,0.9,100.0,M,-20.0,M,,", t);
  feed(std::string("GNRMC,") + utc + ",A,4000.0000,N,10500.0000,W,10.0,90.0,010126,,,A", t + 0.001);
  if (gst) feed(std::string("GNGST,") + utc + ",1.0,,,,0.5,0.6,1.5", t + 0.002);
  return out;
}

TEST(FixAssembler, AnEpochWithoutGstMakesNoPhantomEpochAndTheNextKeepsItsSigma) {
  // uav_log171's u-blox skips GST in some epochs: the assembler once emitted
  // the next epoch at its RMC, then opened a GST-only "epoch" (977 epochs for
  // 960 fixes) and lost that GST.
  NmeaParser p;
  FixAssembler a;
  std::vector<GpsFix> fixes;
  const bool gst[] = {true, true, false, true, true, false, true, true};
  for (int k = 0; k < 8; ++k)
    for (const GpsFix& f : feed_epoch(p, a, k, gst[k])) fixes.push_back(f);
  GpsFix last;
  if (a.flush(last)) fixes.push_back(last);
  ASSERT_EQ(fixes.size(), 8u) << "one fix per receiver epoch";
  for (std::size_t k = 0; k < fixes.size(); ++k) {
    EXPECT_EQ(fixes[k].utc_ms, 12 * 3600 * 1000 + 200 * static_cast<long>(k));
    EXPECT_TRUE(fixes[k].has_position());
    EXPECT_EQ(fixes[k].has_gst, gst[k]) << "epoch " << k << " keeps exactly its own GST";
  }
  EXPECT_EQ(a.late_sentences(), 0u);
}

TEST(FixAssembler, AReceiverThatStopsSendingGstIsFollowedAfterThreeEpochs) {
  NmeaParser p;
  FixAssembler a;
  for (int k = 0; k < 3; ++k) feed_epoch(p, a, k, true);
  // From epoch 3 on no GST: each epoch is first closed by the next one's GGA,
  // until the learned ender is lowered to RMC; then it is emitted at its RMC.
  std::size_t emitted_at_own_rmc = 0;
  for (int k = 3; k < 10; ++k) {
    const auto out = feed_epoch(p, a, k, false);
    for (const GpsFix& f : out) {
      if (f.utc_ms == 12 * 3600 * 1000 + 200 * k) ++emitted_at_own_rmc;
    }
  }
  EXPECT_EQ(emitted_at_own_rmc, 4u) << "epochs 3-5 wait for the next one, 6-9 are emitted at their RMC";
}

TEST(FixAssembler, ASentenceAfterTheLearnedEnderIsCountedLateAndRaisesTheEnder) {
  NmeaParser p;
  FixAssembler a;
  feed_epoch(p, a, 0, false);  // closed by epoch 1's GGA: RMC learned as the ender
  EXPECT_EQ(feed_epoch(p, a, 1, false).size(), 2u) << "epoch 0 closed by time, epoch 1 at its RMC";
  EXPECT_EQ(feed_epoch(p, a, 2, true).size(), 1u) << "epoch 2 at its RMC";
  EXPECT_EQ(a.late_sentences(), 1u) << "epoch 2's GST came after it was emitted";
  const auto out = feed_epoch(p, a, 3, true);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_TRUE(out[0].has_gst) << "GST is now the ender: epoch 3 waits for it";
  EXPECT_EQ(a.late_sentences(), 1u);
}

TEST(FixAssembler, AReceiverRepeatingAnEpochKeepsEveryLaterEpochWhole) {
  // uav_log171's u-blox sent the epoch 23:44:54.00 twice after a 2-s gap. As
  // GGA + VTG (VTG has no time), the repeat's GGA once made GGA the learnt
  // ender and its VTG opened an epoch of its own: every later epoch was then
  // emitted at its GGA with the previous epoch's VTG, its arrival time and
  // velocity 0.2 s old (horizontal RMSE 0.43 -> 0.85 m against the peer).
  NmeaParser p;
  FixAssembler a;
  NmeaMessage m;
  GpsFix fix;
  std::vector<GpsFix> fixes;
  auto feed = [&](const std::string& body, double arrival) {
    ASSERT_EQ(p.parse(with_checksum(body), m), ParseResult::Message) << body;
    if (a.add(m, arrival, fix)) fixes.push_back(fix);
  };
  auto epoch = [&](int k, double arrival) {  // speed k m/s (k x 3.6 km/h) marks whose VTG it is
    char utc[32];
    std::snprintf(utc, sizeof utc, "1200%02d.%02d", k / 5, (k % 5) * 20);
    feed(std::string("GPGGA,") + utc + ",4000.0000,N,10500.0000,W,1,10,0.9,100.0,M,-20.0,M,,", arrival);
    feed("GPVTG,90.0,T,,M,,N," + std::to_string(3.6 * k) + ",K,A", arrival + 0.001);
  };
  for (int k = 1; k <= 3; ++k) epoch(k, 10.0 + 0.2 * k);
  epoch(3, 10.62);  // the repeat
  for (int k = 4; k <= 8; ++k) epoch(k, 10.0 + 0.2 * k);
  if (a.flush(fix)) fixes.push_back(fix);
  ASSERT_EQ(fixes.size(), 8u) << "one fix per epoch, none for the repeat";
  EXPECT_EQ(a.late_sentences(), 2u) << "the repeated GGA and the VTG that followed it";
  for (std::size_t i = 0; i < fixes.size(); ++i) {
    const int k = static_cast<int>(i) + 1;
    EXPECT_EQ(fixes[i].utc_ms, 12 * 3600 * 1000 + 200 * k);
    EXPECT_NEAR(fixes[i].arrival_s, 10.0 + 0.2 * k, 1e-9) << "epoch " << k << " arrives with its GGA";
    ASSERT_TRUE(fixes[i].speed_m_s.has_value());
    EXPECT_NEAR(*fixes[i].speed_m_s, k, 1e-9) << "epoch " << k << " keeps its own VTG";
  }
}

TEST(FixAssembler, NoFixWhenQualityIsZero) {
  NmeaParser p;
  FixAssembler a;
  NmeaMessage m;
  GpsFix fix;
  ASSERT_EQ(p.parse(with_checksum("GPGGA,120000.00,,,,,0,00,99.9,,M,,M,,"), m), ParseResult::Message);
  a.add(m, 1.0, fix);
  ASSERT_TRUE(a.flush(fix));
  EXPECT_FALSE(fix.has_position());
  EXPECT_FALSE(fix.lat_deg.has_value());
}

namespace {

/// One epoch of `sentences` (bodies, no checksum) at UTC 12:00:00, flushed.
GpsFix one_epoch(const std::vector<std::string>& sentences) {
  NmeaParser p;
  FixAssembler a;
  NmeaMessage m;
  GpsFix fix;
  double t = 1.0;
  for (const auto& body : sentences) {
    EXPECT_EQ(p.parse(with_checksum(body), m), ParseResult::Message) << body;
    a.add(m, t += 0.001, fix);
  }
  EXPECT_TRUE(a.flush(fix));
  return fix;
}

// A receiver that has lost the sky extrapolates and says so: GGA quality 6,
// RMC/VTG mode E (u-blox's "dead reckoning fix", gpsd's STATUS_DR); mode N
// is "not valid". Its position and velocity are no measurement: fusing them
// would hide an outage behind the receiver's own guess.
TEST(FixAssembler, AReceiverThatOnlyExtrapolatesGivesNoFix) {
  const std::string gga = "GPGGA,120000.00,4000.0000,N,10500.0000,W,";
  const std::string rmc = "GPRMC,120000.00,A,4000.0000,N,10500.0000,W,10.0,90.0,010126,,,";
  const std::string vtg = "GPVTG,90.0,T,,M,10.0,N,18.5,K,";
  const GpsFix normal = one_epoch({gga + "1,08,0.9,100.0,M,-20.0,M,,", rmc + "A", vtg + "A"});
  EXPECT_TRUE(normal.has_position());
  EXPECT_TRUE(normal.has_velocity());
  for (const auto& epoch : std::vector<std::vector<std::string>>{
           {gga + "6,00,99.9,100.0,M,-20.0,M,,", rmc + "E"},  // u-blox dead reckoning
           {gga + "6,00,99.9,100.0,M,-20.0,M,,"},             // GGA alone
           {rmc + "E"},                                        // RMC alone
           {rmc + "N"},
           {gga + "1,08,0.9,100.0,M,-20.0,M,,", rmc + "A", vtg + "E"}}) {
    const GpsFix f = one_epoch(epoch);
    EXPECT_FALSE(f.has_position()) << epoch[0];
    EXPECT_FALSE(f.has_velocity()) << epoch[0];
  }
  // RTK and a simulator's mode S are measurements.
  EXPECT_TRUE(one_epoch({gga + "4,12,0.6,100.0,M,-20.0,M,1.0,0001", rmc + "R"}).has_position());
  EXPECT_TRUE(one_epoch({rmc + "S"}).has_position());
  // An invalid RMC's speed is not used, even beside a fixed GGA.
  const GpsFix v =
      one_epoch({gga + "1,08,0.9,100.0,M,-20.0,M,,", "GPRMC,120000.00,V,4000.0000,N,10500.0000,W,10.0,90.0,010126,,,A"});
  EXPECT_TRUE(v.has_position());
  EXPECT_FALSE(v.has_velocity());
}

}  // namespace
