#pragma once
// Command-line options of the board's settings (the IMU driver, the devices,
// the GPS set-up), written into a board::FlyConfig: the same words and
// defaults as sinu.toml. `sinu fly` loads its file first and then applies
// only the options given on the command line (they override the file);
// record, convert and replay use the values as they are.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "drivers/imu/icm20948.hpp"
#include "firmware/board/config/fly_config.hpp"

namespace sinu::cli {

class BoardOptions {
 public:
  board::FlyConfig values;  // defaults, then what the command line gave

  /// The IMU driver's settings (mounting, ranges, DLPF, rate).
  void add_imu(CLI::App& cmd);
  /// The devices: I2C bus, data-ready line, GPS port, baud and set-up.
  void add_devices(CLI::App& cmd);
  /// Copies the options that were given into `config` (over a loaded file).
  void apply_given(board::FlyConfig& config) const;
  /// The configuration: `path` (or /etc/sinu/sinu.toml if it exists, else the
  /// defaults, said on stderr), then the options given. False with `error`.
  bool load(const std::string& path, board::FlyConfig& config, std::string& error) const;
  /// The driver configuration of `values.imu`; false with `error` otherwise.
  bool imu_config(drivers::Icm20948Config& out, std::string& error) const;
  /// Whether `name` (e.g. "--accel-range") was given.
  bool given(const std::string& name) const;

  template <class Get>
  CLI::Option* add(CLI::App& cmd, const std::string& name, Get get, const std::string& description) {
    CLI::Option* o = cmd.add_option(name, get(values), description)->capture_default_str();
    overrides_.push_back({o, [get, this](board::FlyConfig& dst) { get(dst) = get(values); }});
    return o;
  }

 private:
  struct Override {
    CLI::Option* option;
    std::function<void(board::FlyConfig&)> apply;
  };
  std::vector<Override> overrides_;
};

}  // namespace sinu::cli
