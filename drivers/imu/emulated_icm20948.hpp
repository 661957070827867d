#pragma once
// A register-level ICM-20948 with its AK09916, behind hal::I2cBus: test and
// replay infrastructure (library sinu_emulator, never linked into the flight
// driver). It answers the transfers the datasheet defines for the registers
// the driver uses, keeps banks, reset and bypass state, quantises each loaded
// sample with the full-scale range the driver configured, and can inject the
// faults a real bus and sensor show (docs/drivers.md).
#include <array>
#include <cstdint>
#include <optional>

#include "drivers/imu/axis_map.hpp"
#include "hal/i2c_bus.hpp"

namespace sinu::drivers {

/// One sample as the airframe saw it (body FRD, SI), to be put in the registers.
struct EmulatedSample {
  std::array<double, 3> specific_force_b_m_s2{};
  std::array<double, 3> angular_rate_b_rad_s{};
  std::optional<std::array<double, 3>> mag_b_uT;  // none: no new magnetometer sample
  double temp_degC = 25.0;
};

enum class EmulatorFault : std::uint8_t {
  None,
  Nack,             // the next `count` transfers are not acknowledged
  WrongWhoAmI,      // WHO_AM_I reads 0x00 (another or no device)
  StuckData,        // data-ready keeps firing but the data registers freeze
  FifoOverflow,     // INT_STATUS_2 reports a FIFO overflow once
  MagOverflow,      // the next `count` magnetometer samples have ST2.HOFL set
  BusDead,          // every transfer times out until cleared
};

class EmulatedIcm20948 final : public hal::I2cBus {
 public:
  explicit EmulatedIcm20948(std::uint8_t address = 0x69, AxisMap mounting = kChipUpToFrd);
  hal::I2cStatus read_registers(std::uint8_t address, std::uint8_t reg, std::span<std::uint8_t> data) override;
  hal::I2cStatus write_registers(std::uint8_t address, std::uint8_t reg, std::span<const std::uint8_t> data) override;

  /// A new conversion: loads the data registers (unless asleep or stuck) and raises data-ready.
  void load(const EmulatedSample& sample);
  /// Starts a fault; `count` limits Nack and MagOverflow (other faults last until clear_faults()).
  void inject(EmulatorFault fault, int count = 1);
  void clear_faults();

  std::uint64_t transfers() const { return transfers_; }
  std::uint64_t resets() const { return resets_; }
  bool bypass_enabled() const;
  std::uint8_t icm_register(int bank, std::uint8_t reg) const { return banks_[static_cast<std::size_t>(bank)][reg & 0x7F]; }

 private:
  hal::I2cStatus bus_fault(std::uint8_t address);
  void reset_icm();
  std::uint8_t read_icm(std::uint8_t reg);
  void write_icm(std::uint8_t reg, std::uint8_t value);
  std::uint8_t read_ak(std::uint8_t reg);
  void write_ak(std::uint8_t reg, std::uint8_t value);
  int bank() const { return (banks_[0][0x7F] >> 4) & 0x03; }

  std::uint8_t address_;
  AxisMap mounting_;
  std::array<std::array<std::uint8_t, 128>, 4> banks_{};
  std::array<std::uint8_t, 0x40> ak_{};
  bool wrong_who_ = false, stuck_ = false, bus_dead_ = false;
  int nack_left_ = 0, mag_overflow_left_ = 0;
  std::uint64_t transfers_ = 0, resets_ = 0;
};

}  // namespace sinu::drivers
