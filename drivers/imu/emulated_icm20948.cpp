#include "drivers/imu/emulated_icm20948.hpp"

#include <algorithm>
#include <cmath>

#include "drivers/imu/icm20948_registers.hpp"

namespace sinu::drivers {

namespace r = icm20948::reg;
namespace b = icm20948::bit;
namespace ak = ak09916;

namespace {

constexpr std::uint8_t kPwr1ResetValue = 0x41;  // asleep, auto clock (datasheet reset value)

std::int16_t quantise(double value, double lsb) {
  if (!std::isfinite(value)) return 0;
  return static_cast<std::int16_t>(std::clamp(std::llround(value / lsb), -32768LL, 32767LL));
}
void put_be16(std::uint8_t* p, std::int16_t v) {
  const auto u = static_cast<std::uint16_t>(v);
  p[0] = static_cast<std::uint8_t>(u >> 8);
  p[1] = static_cast<std::uint8_t>(u);
}
void put_le16(std::uint8_t* p, std::int16_t v) {
  const auto u = static_cast<std::uint16_t>(v);
  p[0] = static_cast<std::uint8_t>(u);
  p[1] = static_cast<std::uint8_t>(u >> 8);
}

}  // namespace

EmulatedIcm20948::EmulatedIcm20948(std::uint8_t address, AxisMap mounting) : address_(address), mounting_(mounting) {
  reset_icm();
  ak_.fill(0);
  ak_[ak::reg::WIA2] = ak::kDeviceIdValue;
  resets_ = 0;
}

void EmulatedIcm20948::reset_icm() {
  for (auto& bank_regs : banks_) bank_regs.fill(0);
  banks_[0][r::WHO_AM_I] = icm20948::kWhoAmIValue;
  banks_[0][r::PWR_MGMT_1] = kPwr1ResetValue;
  banks_[2][r::B2_GYRO_CONFIG_1] = 0x01;
  banks_[2][r::B2_ACCEL_CONFIG] = 0x01;
  ++resets_;
}

bool EmulatedIcm20948::bypass_enabled() const { return (banks_[0][r::INT_PIN_CFG] & b::INT_PIN_BYPASS_EN) != 0; }

void EmulatedIcm20948::inject(EmulatorFault fault, int count) {
  switch (fault) {
    case EmulatorFault::None: break;
    case EmulatorFault::Nack: nack_left_ = count; break;
    case EmulatorFault::WrongWhoAmI: wrong_who_ = true; break;
    case EmulatorFault::StuckData: stuck_ = true; break;
    case EmulatorFault::FifoOverflow: banks_[0][r::INT_STATUS_2] = b::INT2_FIFO_OVERFLOW; break;
    case EmulatorFault::MagOverflow: mag_overflow_left_ = count; break;
    case EmulatorFault::BusDead: bus_dead_ = true; break;
  }
}

void EmulatedIcm20948::clear_faults() {
  wrong_who_ = stuck_ = bus_dead_ = false;
  nack_left_ = mag_overflow_left_ = 0;
}

hal::I2cStatus EmulatedIcm20948::bus_fault(std::uint8_t address) {
  ++transfers_;
  if (bus_dead_) return hal::I2cStatus::Timeout;
  if (nack_left_ > 0) {
    --nack_left_;
    return hal::I2cStatus::Nack;
  }
  if (address != address_ && !(address == ak::kAddress && bypass_enabled())) return hal::I2cStatus::Nack;
  return hal::I2cStatus::Ok;
}

hal::I2cStatus EmulatedIcm20948::read_registers(std::uint8_t address, std::uint8_t reg, std::span<std::uint8_t> data) {
  if (const auto fault = bus_fault(address); fault != hal::I2cStatus::Ok) return fault;
  if (address == address_) {
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = read_icm(static_cast<std::uint8_t>(reg + i));
    return hal::I2cStatus::Ok;
  }
  if (address == ak::kAddress && bypass_enabled()) {
    for (std::size_t i = 0; i < data.size(); ++i) data[i] = read_ak(static_cast<std::uint8_t>(reg + i));
    return hal::I2cStatus::Ok;
  }
  return hal::I2cStatus::Nack;
}

hal::I2cStatus EmulatedIcm20948::write_registers(std::uint8_t address, std::uint8_t reg,
                                                 std::span<const std::uint8_t> data) {
  if (const auto fault = bus_fault(address); fault != hal::I2cStatus::Ok) return fault;
  if (address == address_) {
    for (std::size_t i = 0; i < data.size(); ++i) write_icm(static_cast<std::uint8_t>(reg + i), data[i]);
    return hal::I2cStatus::Ok;
  }
  if (address == ak::kAddress && bypass_enabled()) {
    for (std::size_t i = 0; i < data.size(); ++i) write_ak(static_cast<std::uint8_t>(reg + i), data[i]);
    return hal::I2cStatus::Ok;
  }
  return hal::I2cStatus::Nack;
}

std::uint8_t EmulatedIcm20948::read_icm(std::uint8_t reg) {
  reg &= 0x7F;
  if (reg == r::REG_BANK_SEL) return banks_[0][r::REG_BANK_SEL];
  auto& regs = banks_[static_cast<std::size_t>(bank())];
  const std::uint8_t value = regs[reg];
  if (bank() == 0) {
    if (reg == r::WHO_AM_I && wrong_who_) return 0x00;
    if (reg == r::INT_STATUS_1 || reg == r::INT_STATUS_2) regs[reg] = 0;  // cleared by reading
  }
  return value;
}

void EmulatedIcm20948::write_icm(std::uint8_t reg, std::uint8_t value) {
  reg &= 0x7F;
  if (reg == r::REG_BANK_SEL) {
    for (auto& bank_regs : banks_) bank_regs[r::REG_BANK_SEL] = value & 0x30;
    return;
  }
  if (bank() == 0) {
    if (reg == r::WHO_AM_I || reg == r::INT_STATUS_1 || reg == r::INT_STATUS_2) return;  // read-only
    if (reg == r::PWR_MGMT_1 && (value & b::PWR1_DEVICE_RESET)) {
      reset_icm();
      return;
    }
    if (reg == r::FIFO_RST) return;  // self-clearing on the chip as far as the driver can see
  }
  banks_[static_cast<std::size_t>(bank())][reg] = value;
}

std::uint8_t EmulatedIcm20948::read_ak(std::uint8_t reg) {
  if (reg >= ak_.size()) return 0;
  const std::uint8_t value = ak_[reg];
  if (reg == ak::reg::ST2) ak_[ak::reg::ST1] &= static_cast<std::uint8_t>(~ak::ST1_DRDY);  // reading ST2 ends the read
  return value;
}

void EmulatedIcm20948::write_ak(std::uint8_t reg, std::uint8_t value) {
  if (reg == ak::reg::CNTL3 && (value & ak::CNTL3_SRST)) {
    ak_.fill(0);
    ak_[ak::reg::WIA2] = ak::kDeviceIdValue;
    return;
  }
  if (reg == ak::reg::CNTL2) ak_[reg] = value;
}

void EmulatedIcm20948::load(const EmulatedSample& s) {
  auto& b0 = banks_[0];
  const bool awake = !(b0[r::PWR_MGMT_1] & b::PWR1_SLEEP);
  if (awake && !stuck_) {
    const int accel_fs = (banks_[2][r::B2_ACCEL_CONFIG] >> 1) & 0x03;
    const int gyro_fs = (banks_[2][r::B2_GYRO_CONFIG_1] >> 1) & 0x03;
    const double accel_lsb = icm20948::accel_m_s2_per_lsb(accel_fs);
    const double gyro_lsb = icm20948::gyro_rad_s_per_lsb(gyro_fs);
    const auto accel = mounting_.to_sensor(s.specific_force_b_m_s2);
    const auto gyro = mounting_.to_sensor(s.angular_rate_b_rad_s);
    for (std::size_t i = 0; i < 3; ++i) {
      put_be16(&b0[r::ACCEL_XOUT_H + 2 * i], quantise(accel[i], accel_lsb));
      put_be16(&b0[r::ACCEL_XOUT_H + 6 + 2 * i], quantise(gyro[i], gyro_lsb));
    }
    put_be16(&b0[r::ACCEL_XOUT_H + 12], quantise(s.temp_degC - icm20948::kTempOffsetDegC, 1.0 / icm20948::kTempLsbPerDegC));
  }
  if (awake) b0[r::INT_STATUS_1] |= b::INT1_RAW_DATA_0_RDY;  // set whether or not the INT pin is enabled
  if (s.mag_b_uT && ak_[ak::reg::CNTL2] != 0) {
    const auto m = kMagToChip.to_sensor(mounting_.to_sensor(*s.mag_b_uT));
    for (std::size_t i = 0; i < 3; ++i) put_le16(&ak_[ak::reg::ST1 + 1 + 2 * i], quantise(m[i], ak::kUtPerLsb));
    ak_[ak::reg::ST1] |= ak::ST1_DRDY;
    ak_[ak::reg::ST2] = 0;
    if (mag_overflow_left_ > 0) {
      --mag_overflow_left_;
      ak_[ak::reg::ST2] = ak::ST2_HOFL;
    }
  }
}

}  // namespace sinu::drivers
