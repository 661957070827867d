#pragma once
// ICM-20948 and AK09916 registers and constants used by the driver and its
// emulator (TDK InvenSense ICM-20948 datasheet DS-000189 rev 1.3, section 7-8;
// AKM AK09916 datasheet). Bank-0 registers unless named B2_.
#include <cstdint>

namespace sinu::drivers::icm20948 {

inline constexpr std::uint8_t kAddressAd0Low = 0x68, kAddressAd0High = 0x69;
inline constexpr std::uint8_t kWhoAmIValue = 0xEA;

namespace reg {
inline constexpr std::uint8_t WHO_AM_I = 0x00;
inline constexpr std::uint8_t USER_CTRL = 0x03;
inline constexpr std::uint8_t PWR_MGMT_1 = 0x06;
inline constexpr std::uint8_t PWR_MGMT_2 = 0x07;
inline constexpr std::uint8_t INT_PIN_CFG = 0x0F;
inline constexpr std::uint8_t INT_ENABLE_1 = 0x11;
inline constexpr std::uint8_t INT_STATUS_1 = 0x1A;
inline constexpr std::uint8_t INT_STATUS_2 = 0x1B;
inline constexpr std::uint8_t ACCEL_XOUT_H = 0x2D;  // accel x,y,z, gyro x,y,z, temp: 7 big-endian int16
inline constexpr std::uint8_t FIFO_EN_2 = 0x67;
inline constexpr std::uint8_t FIFO_RST = 0x68;
inline constexpr std::uint8_t REG_BANK_SEL = 0x7F;  // any bank
inline constexpr std::uint8_t B2_GYRO_SMPLRT_DIV = 0x00;
inline constexpr std::uint8_t B2_GYRO_CONFIG_1 = 0x01;
inline constexpr std::uint8_t B2_ACCEL_SMPLRT_DIV_1 = 0x10;
inline constexpr std::uint8_t B2_ACCEL_SMPLRT_DIV_2 = 0x11;
inline constexpr std::uint8_t B2_ACCEL_CONFIG = 0x14;
}  // namespace reg

namespace bit {
inline constexpr std::uint8_t PWR1_DEVICE_RESET = 0x80;
inline constexpr std::uint8_t PWR1_SLEEP = 0x40;
inline constexpr std::uint8_t PWR1_CLKSEL_AUTO = 0x01;
inline constexpr std::uint8_t INT_PIN_BYPASS_EN = 0x02;
inline constexpr std::uint8_t INT1_RAW_DATA_0_RDY = 0x01;
inline constexpr std::uint8_t INT2_FIFO_OVERFLOW = 0x1F;
inline constexpr std::uint8_t CONFIG_FCHOICE = 0x01;  // DLPF enabled
}  // namespace bit

inline constexpr std::uint8_t bank(int b) { return static_cast<std::uint8_t>(b << 4); }
inline constexpr std::size_t kDataBytes = 14;  // accel 6, gyro 6, temp 2

/// Internal sample clock of gyro and accel: ODR = 1125 Hz / (1 + divider).
inline constexpr double kBaseRateHz = 1125.0;
inline constexpr double kStandardGravity_m_s2 = 9.80665;
/// Sensitivity for ACCEL_FS_SEL / GYRO_FS_SEL 0..3 (datasheet tables 1 and 2).
inline constexpr double accel_lsb_per_g(int fs_sel) { return 16384.0 / static_cast<double>(1 << (fs_sel & 3)); }
inline constexpr double gyro_lsb_per_dps(int fs_sel) {
  constexpr double kLsb[4] = {131.0, 65.5, 32.8, 16.4};
  return kLsb[fs_sel & 3];
}
/// SI value of one LSB.
inline constexpr double accel_m_s2_per_lsb(int fs_sel) { return kStandardGravity_m_s2 / accel_lsb_per_g(fs_sel); }
inline constexpr double gyro_rad_s_per_lsb(int fs_sel) { return 3.14159265358979323846 / 180.0 / gyro_lsb_per_dps(fs_sel); }
/// Temperature: degC = raw / 333.87 + 21 (RoomTemp_Offset 0).
inline constexpr double kTempLsbPerDegC = 333.87, kTempOffsetDegC = 21.0;

}  // namespace sinu::drivers::icm20948

namespace sinu::drivers::ak09916 {

inline constexpr std::uint8_t kAddress = 0x0C;  // on the ICM-20948's auxiliary bus, reachable in bypass mode
inline constexpr std::uint8_t kDeviceIdValue = 0x09;
namespace reg {
inline constexpr std::uint8_t WIA2 = 0x01;
inline constexpr std::uint8_t ST1 = 0x10;  // ST1, HXL..HZH, TMPS, ST2: 9 bytes read together
inline constexpr std::uint8_t ST2 = 0x18;
inline constexpr std::uint8_t CNTL2 = 0x31;
inline constexpr std::uint8_t CNTL3 = 0x32;
}  // namespace reg
inline constexpr std::uint8_t ST1_DRDY = 0x01;
inline constexpr std::uint8_t ST2_HOFL = 0x08;  // magnetic sensor overflow: the sample is invalid
inline constexpr std::uint8_t CNTL2_CONTINUOUS_100HZ = 0x08;
inline constexpr std::uint8_t CNTL3_SRST = 0x01;
inline constexpr std::size_t kBlockBytes = 9;
inline constexpr double kUtPerLsb = 0.15;

}  // namespace sinu::drivers::ak09916
