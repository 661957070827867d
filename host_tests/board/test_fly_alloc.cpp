// The fly loop allocates nothing per sample: the board loop, the drivers, the
// navigation unit, MAVLink, NMEA, the navigation log and the health lines
// run over a 5- and a 15-minute flight with the same number of heap
// allocations (all of them before the first sample: buffers, the first
// health line's stdio). The devices are the emulator's, in process.
#include <gtest/gtest.h>

#include <cstdio>

#include "drivers/imu/emulated_icm20948.hpp"
#include "firmware/board/fly_loop.hpp"
#include "firmware/host/convert/dataset_devices.hpp"
#include "hal/linux/monotonic_clock.hpp"
#include "host_tests/board/fly_flight.hpp"
#include "host_tests/support/alloc_counter.hpp"

namespace sinu::test {
namespace {

class NullSocket final : public hal::DatagramSocket {
 public:
  hal::DatagramStatus send(std::span<const std::uint8_t>) override { return hal::DatagramStatus::Ok; }
};
class NullSerial final : public hal::SerialPort {
 public:
  bool set_baud(std::uint32_t) override { return true; }
  hal::SerialResult read(std::span<std::uint8_t>, hal::TimeNs) override { return {}; }
  hal::SerialResult write(std::span<const std::uint8_t> b) override { return {hal::SerialStatus::Ok, b.size(), 0}; }
};

struct FlightRun {
  std::uint64_t allocations = 0, samples = 0, solutions = 0;
  bool aligned = false;
};

FlightRun fly_in_process(const std::string& dataset, const std::string& log) {
  hal::ManualClock clock;
  drivers::Icm20948Config imu;
  drivers::EmulatedIcm20948 chip(imu.address, imu.mounting);
  convert::DatasetDevices data(chip, clock);
  EXPECT_TRUE(data.open(dataset));
  clock.advance_to_ns(data.first_time_ns() - 1'000'000'000);
  NullSocket socket;
  NullSerial nmea_port;
  board::MavlinkOutput mavlink({}, socket);
  board::NmeaOutput nmea(nmea_port, {});
  board::FlyOutputs outputs;
  outputs.mavlink = &mavlink;
  outputs.nmea = &nmea;
  outputs.log_path = log;
  board::FlyLoopConfig cfg;
  cfg.health_period_s = 1e-3;  // many health lines: their formatting is in the loop too
  std::FILE* devnull = std::fopen("/dev/null", "w");
  cfg.health = devnull;
  hal::MonotonicClock wall;
  board::FlyLoop loop({data, chip, data, clock}, imu, outputs, wall, cfg);
  board::NavUnitConfig unit;
  std::string error;
  EXPECT_TRUE(loop.init(unit, error)) << error;
  FlightRun r;
  {
    AllocationScope scope;
    loop.run(nullptr, 0);
    r.allocations = scope.count();
  }
  EXPECT_TRUE(loop.close_log(error)) << error;
  std::fclose(devnull);
  r.samples = loop.board().imu().counters().samples;
  r.solutions = loop.solutions();
  r.aligned = loop.unit().navigator().aligned();
  return r;
}

TEST(FlyAlloc, NoHeapAllocationPerSample) {
  TempDir tmp;
  const FlyFlight a = make_fly_flight(tmp, "short", 300, 31), b = make_fly_flight(tmp, "long", 900, 31);
  const FlightRun ra = fly_in_process(a.quantised, tmp.file("a.csv")), rb = fly_in_process(b.quantised, tmp.file("b.csv"));
  std::printf("allocations in the loop: %llu (300 s, %llu samples), %llu (900 s, %llu samples)\n",
              static_cast<unsigned long long>(ra.allocations), static_cast<unsigned long long>(ra.samples),
              static_cast<unsigned long long>(rb.allocations), static_cast<unsigned long long>(rb.samples));
  ASSERT_TRUE(ra.aligned && rb.aligned);
  EXPECT_GT(rb.samples, 3 * ra.samples - 100);
  EXPECT_GT(rb.solutions, 30000u);
  EXPECT_EQ(rb.allocations, ra.allocations) << "an allocation that grows with the flight";
}

}  // namespace
}  // namespace sinu::test
