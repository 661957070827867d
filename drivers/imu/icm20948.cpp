#include "drivers/imu/icm20948.hpp"

#include <algorithm>
#include <cmath>

#include "drivers/imu/icm20948_registers.hpp"

namespace sinu::drivers {

namespace r = icm20948::reg;
namespace b = icm20948::bit;
namespace ak = ak09916;

namespace {

constexpr hal::TimeNs kWakeWaitNs = 20'000'000;   // clock settles after leaving sleep
constexpr hal::TimeNs kMagResetWaitNs = 10'000'000;

std::int16_t be16(const std::uint8_t* p) { return static_cast<std::int16_t>((p[0] << 8) | p[1]); }
std::int16_t le16(const std::uint8_t* p) { return static_cast<std::int16_t>((p[1] << 8) | p[0]); }

}  // namespace

Icm20948::Icm20948(hal::I2cBus& bus, hal::Clock& clock, const Icm20948Config& config)
    : bus_(bus), clock_(clock), config_(config) {}

std::uint8_t Icm20948::divider() const {
  const double d = std::round(icm20948::kBaseRateHz / config_.odr_hz - 1.0);
  return static_cast<std::uint8_t>(std::clamp(d, 0.0, 255.0));
}

double Icm20948::actual_odr_hz() const { return icm20948::kBaseRateHz / (1.0 + divider()); }

bool Icm20948::write(std::uint8_t address, std::uint8_t reg, std::uint8_t value) {
  if (bus_.write_registers(address, reg, {&value, 1}) == hal::I2cStatus::Ok) return true;
  ++counters_.i2c_errors;
  return false;
}

bool Icm20948::read(std::uint8_t address, std::uint8_t reg, std::uint8_t* data, std::size_t n) {
  if (bus_.read_registers(address, reg, {data, n}) == hal::I2cStatus::Ok) return true;
  ++counters_.i2c_errors;
  return false;
}

bool Icm20948::write_checked(std::uint8_t reg, std::uint8_t value) {
  std::uint8_t back = 0;
  if (!write(config_.address, reg, value) || !read(config_.address, reg, &back, 1)) return false;
  if (back == value) return true;
  ++counters_.config_mismatch;
  return false;
}

bool Icm20948::select_bank(int bank) { return write(config_.address, r::REG_BANK_SEL, icm20948::bank(bank)); }

bool Icm20948::configure() {
  const auto dlpf = static_cast<std::uint8_t>((config_.dlpf & 0x07) << 3);
  const std::uint8_t div = divider();
  const auto gyro_cfg = static_cast<std::uint8_t>(dlpf | (static_cast<int>(config_.gyro_range) << 1) | b::CONFIG_FCHOICE);
  const auto accel_cfg =
      static_cast<std::uint8_t>(dlpf | (static_cast<int>(config_.accel_range) << 1) | b::CONFIG_FCHOICE);
  return select_bank(0) && write_checked(r::PWR_MGMT_2, 0x00) &&  // accel and gyro on
         write_checked(r::USER_CTRL, 0x00) &&                     // no I2C master, no FIFO, no DMP
         write_checked(r::FIFO_EN_2, 0x00) &&
         write_checked(r::INT_PIN_CFG, b::INT_PIN_BYPASS_EN) &&   // INT active high, pulse; AK09916 on our bus
         write_checked(r::INT_ENABLE_1, b::INT1_RAW_DATA_0_RDY) && select_bank(2) &&
         write_checked(r::B2_GYRO_SMPLRT_DIV, div) && write_checked(r::B2_GYRO_CONFIG_1, gyro_cfg) &&
         write_checked(r::B2_ACCEL_SMPLRT_DIV_1, 0x00) && write_checked(r::B2_ACCEL_SMPLRT_DIV_2, div) &&
         write_checked(r::B2_ACCEL_CONFIG, accel_cfg) && select_bank(0);
}

bool Icm20948::configure_magnetometer() {
  std::uint8_t id = 0;
  if (!read(ak::kAddress, ak::reg::WIA2, &id, 1)) return false;
  if (id != ak::kDeviceIdValue) {
    ++counters_.wrong_whoami;
    return false;
  }
  if (!write(ak::kAddress, ak::reg::CNTL3, ak::CNTL3_SRST)) return false;
  clock_.sleep_until_ns(clock_.now_ns() + kMagResetWaitNs);
  std::uint8_t mode = 0;
  if (!write(ak::kAddress, ak::reg::CNTL2, ak::CNTL2_CONTINUOUS_100HZ) || !read(ak::kAddress, ak::reg::CNTL2, &mode, 1))
    return false;
  if (mode != ak::CNTL2_CONTINUOUS_100HZ) {
    ++counters_.config_mismatch;
    return false;
  }
  return true;
}

bool Icm20948::init() {
  ++counters_.init_attempts;
  ever_tried_ = true;
  last_init_ns_ = clock_.now_ns();
  ready_ = false;
  repeats_ = 0;
  consecutive_errors_ = 0;
  std::uint8_t who = 0;
  bool ok = select_bank(0) && read(config_.address, r::WHO_AM_I, &who, 1);
  if (ok && who != icm20948::kWhoAmIValue) {
    ++counters_.wrong_whoami;
    ok = false;
  }
  ok = ok && write(config_.address, r::PWR_MGMT_1, b::PWR1_DEVICE_RESET);
  if (ok) clock_.sleep_until_ns(clock_.now_ns() + config_.reset_wait_ns);
  ok = ok && select_bank(0) && write_checked(r::PWR_MGMT_1, b::PWR1_CLKSEL_AUTO);  // wake, auto clock
  if (ok) clock_.sleep_until_ns(clock_.now_ns() + kWakeWaitNs);
  ok = ok && configure() && configure_magnetometer();
  if (!ok) {
    ++counters_.init_failures;
    return false;
  }
  std::uint8_t status[2] = {};  // clear any data-ready raised during configuration
  ready_ = read(config_.address, r::INT_STATUS_1, status, 2);
  if (!ready_) ++counters_.init_failures;
  return ready_;
}

ImuRead Icm20948::fail() {
  if (++consecutive_errors_ >= config_.max_consecutive_errors) {
    ready_ = false;  // the next read() re-initialises
    ++counters_.reinits;
  }
  return ImuRead::Error;
}

ImuRead Icm20948::read(hal::TimeNs edge_ns, ImuSample& out) { return read_sample(edge_ns, out, false); }

ImuRead Icm20948::poll(hal::TimeNs now_ns, ImuSample& out) {
  const ImuRead r = read_sample(now_ns, out, true);
  if (r == ImuRead::Sample) ++counters_.polled;
  return r;
}

ImuRead Icm20948::read_sample(hal::TimeNs edge_ns, ImuSample& out, bool polled) {
  if (!ready_) {
    if (ever_tried_ && clock_.now_ns() - last_init_ns_ < config_.reinit_backoff_ns) return ImuRead::Error;
    if (!init()) return ImuRead::Error;
  }
  if (have_last_ && edge_ns <= last_sample_ns_) {  // the same edge twice, or time went backwards
    ++counters_.stale_edges;
    return ImuRead::NoData;
  }
  std::uint8_t status[2] = {};
  if (!read(config_.address, r::INT_STATUS_1, status, 2)) return fail();
  if (status[1] & b::INT2_FIFO_OVERFLOW) {
    // We never enable the FIFO: the flag means a glitch re-enabled it. Reset
    // it and re-check the configuration on the next edge.
    ++counters_.fifo_overflow;
    if (!write(config_.address, r::FIFO_RST, 0x1F) || !write(config_.address, r::FIFO_RST, 0x00) ||
        !write_checked(r::USER_CTRL, 0x00) || !write_checked(r::FIFO_EN_2, 0x00))
      return fail();
  }
  if (!(status[0] & b::INT1_RAW_DATA_0_RDY)) {
    ++(polled ? counters_.polls_empty : counters_.no_new_data);
    return ImuRead::NoData;
  }
  std::array<std::uint8_t, icm20948::kDataBytes> raw{};
  if (!read(config_.address, r::ACCEL_XOUT_H, raw.data(), raw.size())) return fail();
  if (have_last_ && raw == last_raw_) {
    ++counters_.repeated_samples;
    if (config_.stuck_limit > 0 && ++repeats_ >= config_.stuck_limit) {
      ++counters_.stuck_data;
      ready_ = false;
      ++counters_.reinits;
      return ImuRead::Error;
    }
  } else {
    repeats_ = 0;
  }
  std::array<std::uint8_t, ak::kBlockBytes> mag{};
  bool mag_ok = false;
  if (read(ak::kAddress, ak::reg::ST1, mag.data(), mag.size())) {
    if (mag[8] & ak::ST2_HOFL) ++counters_.mag_overflow;
    else mag_ok = (mag[0] & ak::ST1_DRDY) != 0;
  } else {
    ++counters_.mag_errors;
  }
  consecutive_errors_ = 0;
  last_raw_ = raw;
  have_last_ = true;
  last_sample_ns_ = edge_ns;
  out.t_ns = edge_ns;
  decode(raw.data(), mag.data(), mag_ok, out);
  ++counters_.samples;
  return ImuRead::Sample;
}

void Icm20948::decode(const std::uint8_t* raw, const std::uint8_t* mag, bool mag_ok, ImuSample& out) const {
  const double accel_scale = icm20948::accel_m_s2_per_lsb(static_cast<int>(config_.accel_range));
  const double gyro_scale = icm20948::gyro_rad_s_per_lsb(static_cast<int>(config_.gyro_range));
  std::array<double, 3> accel{}, gyro{};
  for (std::size_t i = 0; i < 3; ++i) {
    accel[i] = be16(raw + 2 * i) * accel_scale;
    gyro[i] = be16(raw + 6 + 2 * i) * gyro_scale;
  }
  out.specific_force_b_m_s2 = config_.mounting.to_body(accel);
  out.angular_rate_b_rad_s = config_.mounting.to_body(gyro);
  out.temp_degC = be16(raw + 12) / icm20948::kTempLsbPerDegC + icm20948::kTempOffsetDegC;
  out.has_mag = mag_ok;
  if (mag_ok) {
    std::array<double, 3> m{};
    for (std::size_t i = 0; i < 3; ++i) m[i] = le16(mag + 1 + 2 * i) * ak::kUtPerLsb;
    out.mag_b_uT = config_.mounting.to_body(kMagToChip.to_body(m));
  } else {
    out.mag_b_uT = {};
  }
}

}  // namespace sinu::drivers
