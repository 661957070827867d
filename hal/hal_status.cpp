#include "hal/i2c_bus.hpp"

namespace sinu::hal {

const char* to_string(I2cStatus s) {
  switch (s) {
    case I2cStatus::Ok: return "ok";
    case I2cStatus::Nack: return "no acknowledge";
    case I2cStatus::Timeout: return "bus timeout";
    case I2cStatus::BusError: return "bus error";
    case I2cStatus::Io: return "I/O error";
  }
  return "unknown";
}

}  // namespace sinu::hal
