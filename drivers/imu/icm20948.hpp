#pragma once
// ICM-20948 (accel, gyro, temperature) + AK09916 (magnetometer) over I2C.
//
// The magnetometer is reached in the ICM-20948's bypass mode (INT_PIN_CFG
// BYPASS_EN): the host talks to the AK09916 at 0x0C on the same bus. This
// costs a second transfer per sample (9 bytes) but keeps the ICM-20948's
// internal I2C master, its slave registers and their timing out of the
// driver (docs/drivers.md).
//
// Sampling: the data-ready interrupt (INT pin, RAW_DATA_0_RDY) marks each new
// accel/gyro sample; the caller waits for its edge and passes the edge time.
// A sample is delivered only if INT_STATUS_1 says it is new (the status is
// cleared by reading it), and only once: a stale or repeated sample is
// counted, never delivered as new.
//
// Recovery: after max_consecutive_errors failed samples, or a stuck sensor,
// the driver re-initialises (probe, reset, configure with read-back), at most
// once per reinit_backoff while it keeps failing.
#include <array>
#include <cstdint>

#include "drivers/imu/axis_map.hpp"
#include "hal/clock.hpp"
#include "hal/i2c_bus.hpp"

namespace sinu::drivers {

enum class AccelRange : std::uint8_t { G2 = 0, G4 = 1, G8 = 2, G16 = 3 };
enum class GyroRange : std::uint8_t { Dps250 = 0, Dps500 = 1, Dps1000 = 2, Dps2000 = 3 };

struct Icm20948Config {
  std::uint8_t address = 0x69;  // AD0 high (0x68 with AD0 low)
  AccelRange accel_range = AccelRange::G8;
  GyroRange gyro_range = GyroRange::Dps1000;
  /// DLPF setting 0..7 for gyro and accel (5: ~12 Hz bandwidth, below the
  /// 20 Hz Nyquist frequency of 40 Hz sampling).
  std::uint8_t dlpf = 5;
  /// Output data rate; the chip gives 1125 / (1 + divider) Hz, so 40 Hz
  /// becomes divider 27 = 40.18 Hz (samples carry the edge time, not n/ODR).
  double odr_hz = 40.0;
  AxisMap mounting = kChipUpToFrd;  // chip axes -> body FRD
  int max_consecutive_errors = 5;
  /// Identical raw samples (all 7 words) in a row that mean "stuck"; a real
  /// MEMS sensor's noise makes even 2 in a row rare (0 disables the check).
  int stuck_limit = 40;
  hal::TimeNs reset_wait_ns = 100'000'000;  // after DEVICE_RESET (datasheet start-up time)
  hal::TimeNs reinit_backoff_ns = 1'000'000'000;
};

struct ImuSample {
  hal::TimeNs t_ns = 0;  // data-ready edge time (monotonic clock)
  std::array<double, 3> specific_force_b_m_s2{};
  std::array<double, 3> angular_rate_b_rad_s{};
  bool has_mag = false;
  std::array<double, 3> mag_b_uT{};
  double temp_degC = 0.0;
};

struct Icm20948Counters {
  std::uint64_t samples = 0;         // delivered
  std::uint64_t i2c_errors = 0;      // failed transfers of any kind (NACK, timeout, ...)
  std::uint64_t wrong_whoami = 0;    // probe found another device (or none)
  std::uint64_t config_mismatch = 0; // a configuration register did not read back
  std::uint64_t init_attempts = 0, init_failures = 0;
  std::uint64_t reinits = 0;         // re-initialisations after failures
  std::uint64_t no_new_data = 0;     // an edge without a new sample (not delivered)
  std::uint64_t stale_edges = 0;     // an edge not later than the last delivered sample
  std::uint64_t repeated_samples = 0;// raw sample identical to the previous one
  std::uint64_t stuck_data = 0;      // stuck_limit repeats in a row: sensor declared stuck
  std::uint64_t fifo_overflow = 0;   // FIFO overflow flag seen (FIFO reset, config re-checked)
  std::uint64_t mag_overflow = 0;    // AK09916 HOFL: magnetometer sample dropped
  std::uint64_t mag_errors = 0;      // magnetometer transfer failed: sample without mag
  std::uint64_t polled = 0;          // samples read by poll() (no data-ready edge)
  std::uint64_t polls_empty = 0;     // polls that found no new sample (expected: polls run faster than the ODR)
};

enum class ImuRead { Sample, NoData, Error };

class Icm20948 {
 public:
  Icm20948(hal::I2cBus& bus, hal::Clock& clock, const Icm20948Config& config = {});
  /// Probe, reset and configure. False leaves the driver uninitialised (read() retries).
  bool init();
  /// Reads the sample announced by a data-ready edge at `edge_ns`.
  ImuRead read(hal::TimeNs edge_ns, ImuSample& out);
  /// Without edges (the data-ready line broke): reads a sample if the chip
  /// has a new one (INT_STATUS_1), stamped `now_ns`, the poll's time (up to
  /// the polling period later than the conversion). NoData is normal here.
  ImuRead poll(hal::TimeNs now_ns, ImuSample& out);
  bool initialised() const { return ready_; }
  const Icm20948Counters& counters() const { return counters_; }
  /// Actual output data rate after the divider's rounding.
  double actual_odr_hz() const;
  std::uint8_t divider() const;

 private:
  bool write(std::uint8_t address, std::uint8_t reg, std::uint8_t value);
  bool write_checked(std::uint8_t reg, std::uint8_t value);
  bool read(std::uint8_t address, std::uint8_t reg, std::uint8_t* data, std::size_t n);
  bool select_bank(int bank);
  bool configure();
  bool configure_magnetometer();
  ImuRead fail();
  ImuRead read_sample(hal::TimeNs t_ns, ImuSample& out, bool polled);
  void decode(const std::uint8_t* raw, const std::uint8_t* mag, bool mag_ok, ImuSample& out) const;

  hal::I2cBus& bus_;
  hal::Clock& clock_;
  Icm20948Config config_;
  bool ready_ = false;
  bool ever_tried_ = false;
  hal::TimeNs last_init_ns_ = 0;
  hal::TimeNs last_sample_ns_ = 0;
  bool have_last_ = false;
  int consecutive_errors_ = 0;
  int repeats_ = 0;
  std::array<std::uint8_t, 14> last_raw_{};
  Icm20948Counters counters_;
};

}  // namespace sinu::drivers
