// ICM-20948 + AK09916 driver against the register-level emulator: start-up
// sequence, scaling, axis mapping, and every injected fault -> counter -> recovery.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "drivers/imu/emulated_icm20948.hpp"
#include "drivers/imu/icm20948.hpp"
#include "drivers/imu/icm20948_registers.hpp"
#include "hal/replay/manual_clock.hpp"

using namespace sinu::drivers;
using sinu::hal::ManualClock;
using sinu::hal::TimeNs;

namespace {

constexpr double kG = 9.80665;
constexpr TimeNs kPeriodNs = 25'000'000;  // 40 Hz
// Half a quantisation step of the default ranges: the most a value can move
// through register quantisation (accel +-8 g: 1/4096 g; gyro +-1000 dps:
// 1/32.8 dps; magnetometer 0.15 uT; temperature 1/333.87 degC).
constexpr double kAccelTol = 0.5 * kG / 4096.0;
constexpr double kGyroTol = 0.5 * std::numbers::pi / 180.0 / 32.8;
constexpr double kMagTol = 0.5 * 0.15;
constexpr double kTempTol = 0.5 / 333.87;

EmulatedSample level_at_rest(double wobble = 0.0) {
  EmulatedSample s;
  s.specific_force_b_m_s2 = {0.1 + wobble, -0.2, -kG};
  s.angular_rate_b_rad_s = {0.01, -0.02, 0.5 + wobble};
  s.mag_b_uT = std::array<double, 3>{21.0, -3.0, 43.5};
  s.temp_degC = 31.25;
  return s;
}

struct Rig {
  ManualClock clock{1'000'000'000};
  EmulatedIcm20948 chip;
  Icm20948 imu{chip, clock};
  TimeNs t_ns = 2'000'000'000;
  int k = 0;

  // One data-ready period: the chip converts, the edge arrives, the driver reads.
  ImuRead step(ImuSample& out, bool convert = true) {
    t_ns += kPeriodNs;
    clock.advance_to_ns(t_ns);
    if (convert) chip.load(level_at_rest(1e-3 * (k++ % 7)));  // small changes: a live sensor
    return imu.read(t_ns, out);
  }
};

}  // namespace

TEST(Icm20948, StartUpSequenceConfiguresRangesFilterRateAndBypass) {
  Rig rig;
  const TimeNs before = rig.clock.now_ns();
  ASSERT_TRUE(rig.imu.init());
  EXPECT_EQ(rig.chip.resets(), 1u) << "one DEVICE_RESET";
  EXPECT_GE(rig.clock.now_ns() - before, 100'000'000) << "waits the start-up time after reset";
  namespace r = icm20948::reg;
  EXPECT_EQ(rig.chip.icm_register(2, r::B2_GYRO_SMPLRT_DIV), 27) << "1125/(1+27) = 40.18 Hz";
  EXPECT_NEAR(rig.imu.actual_odr_hz(), 40.18, 0.01);
  EXPECT_EQ(rig.chip.icm_register(2, r::B2_GYRO_CONFIG_1), (5 << 3) | (2 << 1) | 1) << "DLPF 5, +-1000 dps";
  EXPECT_EQ(rig.chip.icm_register(2, r::B2_ACCEL_CONFIG), (5 << 3) | (2 << 1) | 1) << "DLPF 5, +-8 g";
  EXPECT_EQ(rig.chip.icm_register(2, r::B2_ACCEL_SMPLRT_DIV_2), 27);
  EXPECT_EQ(rig.chip.icm_register(0, r::PWR_MGMT_1), 0x01) << "awake, auto clock";
  EXPECT_EQ(rig.chip.icm_register(0, r::INT_ENABLE_1), 0x01) << "data-ready interrupt";
  EXPECT_TRUE(rig.chip.bypass_enabled());
  EXPECT_EQ(rig.imu.counters().config_mismatch, 0u);
}

TEST(Icm20948, ScalesToSiAndMapsChipAxesToFrd) {
  Rig rig;
  ASSERT_TRUE(rig.imu.init());
  ImuSample s;
  rig.clock.advance_to_ns(rig.t_ns += kPeriodNs);
  const EmulatedSample in = level_at_rest();
  rig.chip.load(in);
  ASSERT_EQ(rig.imu.read(rig.t_ns, s), ImuRead::Sample);
  EXPECT_EQ(s.t_ns, rig.t_ns);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(s.specific_force_b_m_s2[i], in.specific_force_b_m_s2[i], kAccelTol) << i;
    EXPECT_NEAR(s.angular_rate_b_rad_s[i], in.angular_rate_b_rad_s[i], kGyroTol) << i;
    EXPECT_NEAR(s.mag_b_uT[i], (*in.mag_b_uT)[i], kMagTol) << i;
  }
  EXPECT_TRUE(s.has_mag);
  EXPECT_NEAR(s.temp_degC, in.temp_degC, kTempTol);
  // The physics of the mapping, from the registers themselves: level and at
  // rest, the chip's z axis (up, component side) reads +1 g = +4096 LSB at
  // +-8 g, and FRD z (down) is -g.
  namespace r = icm20948::reg;
  const int az_raw = static_cast<std::int16_t>((rig.chip.icm_register(0, r::ACCEL_XOUT_H + 4) << 8) |
                                               rig.chip.icm_register(0, r::ACCEL_XOUT_H + 5));
  EXPECT_EQ(az_raw, 4096);
  EXPECT_NEAR(s.specific_force_b_m_s2[2], -kG, kAccelTol);
}

TEST(Icm20948, ConfigurableMountingRotation) {
  // Board turned 90 deg about z: chip x points right, chip y forward.
  const auto mounting = AxisMap::parse("y,x,-z");
  ASSERT_TRUE(mounting);
  ManualClock clock;
  EmulatedIcm20948 chip(0x69, *mounting);
  Icm20948Config cfg;
  cfg.mounting = *mounting;
  Icm20948 imu(chip, clock, cfg);
  ASSERT_TRUE(imu.init());
  EmulatedSample in = level_at_rest();
  in.specific_force_b_m_s2 = {2.0, -1.0, -kG};  // 2 m/s^2 forward
  chip.load(in);
  ImuSample s;
  ASSERT_EQ(imu.read(1, s), ImuRead::Sample);
  EXPECT_NEAR(s.specific_force_b_m_s2[0], 2.0, kAccelTol);
  EXPECT_NEAR(s.specific_force_b_m_s2[1], -1.0, kAccelTol);
  namespace r = icm20948::reg;
  const int ay_chip = static_cast<std::int16_t>((chip.icm_register(0, r::ACCEL_XOUT_H + 2) << 8) |
                                                chip.icm_register(0, r::ACCEL_XOUT_H + 3));
  EXPECT_EQ(ay_chip, std::lround(2.0 / (kG / 4096.0))) << "forward is the chip's y axis";
  EXPECT_FALSE(AxisMap::parse("x,x,z"));
  EXPECT_FALSE(AxisMap::parse("x,y"));
}

TEST(Icm20948, NeverDeliversAStaleSampleOrTheSameOneTwice) {
  Rig rig;
  ASSERT_TRUE(rig.imu.init());
  ImuSample s;
  ASSERT_EQ(rig.step(s), ImuRead::Sample);
  const TimeNs t = s.t_ns;
  EXPECT_EQ(rig.imu.read(t, s), ImuRead::NoData) << "the same edge again";
  EXPECT_EQ(rig.imu.counters().stale_edges, 1u);
  EXPECT_EQ(rig.step(s, /*convert=*/false), ImuRead::NoData) << "an edge without a conversion";
  EXPECT_EQ(rig.imu.counters().no_new_data, 1u);
  EXPECT_EQ(rig.step(s), ImuRead::Sample);
  EXPECT_EQ(rig.imu.counters().samples, 2u);
}

TEST(Icm20948, NackDropsOneSampleThenRecovers) {
  Rig rig;
  ASSERT_TRUE(rig.imu.init());
  ImuSample s;
  rig.chip.inject(EmulatorFault::Nack, 1);
  EXPECT_EQ(rig.step(s), ImuRead::Error);
  EXPECT_EQ(rig.imu.counters().i2c_errors, 1u);
  EXPECT_EQ(rig.step(s), ImuRead::Sample);
  EXPECT_EQ(rig.imu.counters().reinits, 0u);
}

TEST(Icm20948, RepeatedFailuresReinitialise) {
  Rig rig;
  ASSERT_TRUE(rig.imu.init());
  ImuSample s;
  rig.chip.inject(EmulatorFault::Nack, 5);  // max_consecutive_errors
  for (int i = 0; i < 5; ++i) EXPECT_EQ(rig.step(s), ImuRead::Error);
  EXPECT_EQ(rig.imu.counters().reinits, 1u);
  EXPECT_FALSE(rig.imu.initialised());
  // The first edge re-initialises; the conversion it announced predates the
  // reset (init clears data-ready), so it is not delivered.
  EXPECT_EQ(rig.step(s), ImuRead::NoData);
  EXPECT_TRUE(rig.imu.initialised());
  EXPECT_EQ(rig.chip.resets(), 2u);
  EXPECT_EQ(rig.step(s), ImuRead::Sample);
}

TEST(Icm20948, WrongWhoAmIFailsProbeUntilTheRightChipAnswers) {
  Rig rig;
  rig.chip.inject(EmulatorFault::WrongWhoAmI);
  EXPECT_FALSE(rig.imu.init());
  EXPECT_EQ(rig.imu.counters().wrong_whoami, 1u);
  EXPECT_EQ(rig.chip.resets(), 0u) << "never reset a device we did not identify";
  rig.chip.clear_faults();
  rig.t_ns = rig.clock.now_ns();
  ImuSample s;
  EXPECT_EQ(rig.step(s), ImuRead::Error) << "within the 1 s back-off: no retry yet";
  EXPECT_EQ(rig.imu.counters().init_attempts, 1u);
  rig.t_ns += 1'000'000'000;
  EXPECT_EQ(rig.step(s), ImuRead::NoData) << "re-initialised; the older conversion is dropped";
  EXPECT_TRUE(rig.imu.initialised());
  EXPECT_EQ(rig.step(s), ImuRead::Sample);
}

TEST(Icm20948, StuckDataIsDetectedAndReinitialises) {
  Rig rig;
  ASSERT_TRUE(rig.imu.init());
  ImuSample s;
  ASSERT_EQ(rig.step(s), ImuRead::Sample);
  rig.chip.inject(EmulatorFault::StuckData);
  int delivered = 0;
  for (int i = 0; i < 40; ++i) delivered += rig.step(s) == ImuRead::Sample;
  EXPECT_EQ(rig.imu.counters().stuck_data, 1u);
  EXPECT_EQ(rig.imu.counters().repeated_samples, 40u);
  EXPECT_EQ(delivered, 39) << "the 40th repeat declares the sensor stuck";
  EXPECT_FALSE(rig.imu.initialised());
  rig.chip.clear_faults();
  rig.step(s);  // re-initialises
  EXPECT_EQ(rig.step(s), ImuRead::Sample);
}

TEST(Icm20948, FifoOverflowIsCountedResetAndSampleKept) {
  Rig rig;
  ASSERT_TRUE(rig.imu.init());
  ImuSample s;
  rig.chip.inject(EmulatorFault::FifoOverflow);
  EXPECT_EQ(rig.step(s), ImuRead::Sample);
  EXPECT_EQ(rig.imu.counters().fifo_overflow, 1u);
  EXPECT_EQ(rig.chip.icm_register(0, icm20948::reg::FIFO_EN_2), 0);
  EXPECT_EQ(rig.step(s), ImuRead::Sample);
  EXPECT_EQ(rig.imu.counters().fifo_overflow, 1u);
}

TEST(Icm20948, MagnetometerOverflowDropsOnlyTheMagSample) {
  Rig rig;
  ASSERT_TRUE(rig.imu.init());
  ImuSample s;
  rig.chip.inject(EmulatorFault::MagOverflow, 1);
  ASSERT_EQ(rig.step(s), ImuRead::Sample);
  EXPECT_FALSE(s.has_mag);
  EXPECT_EQ(rig.imu.counters().mag_overflow, 1u);
  ASSERT_EQ(rig.step(s), ImuRead::Sample);
  EXPECT_TRUE(s.has_mag);
}

TEST(Icm20948, DeadBusBacksOffAndRecoversWhenTheBusReturns) {
  Rig rig;
  ASSERT_TRUE(rig.imu.init());
  ImuSample s;
  rig.chip.inject(EmulatorFault::BusDead);
  for (int i = 0; i < 200; ++i) EXPECT_NE(rig.step(s), ImuRead::Sample);  // 5 s of edges
  const auto& c = rig.imu.counters();
  EXPECT_EQ(c.reinits, 1u);
  // One attempt per second of back-off over the ~4.9 s after the reinit decision.
  EXPECT_GE(c.init_failures, 4u);
  EXPECT_LE(c.init_failures, 6u);
  rig.chip.clear_faults();
  int samples = 0;
  for (int i = 0; i < 80; ++i) samples += rig.step(s) == ImuRead::Sample;
  EXPECT_TRUE(rig.imu.initialised());
  EXPECT_GE(samples, 79 - 40) << "back within one back-off period";
}
