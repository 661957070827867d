#pragma once
// Clipping of one imu.csv row (ImuClip in dataset_faults.hpp says exactly how).
#include <string>
#include <vector>

#include "host_tests/support/dataset_faults.hpp"

namespace sinu::test::faults {

/// Clips the chosen accel/gyro fields of a row at time t, in place; true if
/// any field's text changed. Fields that are empty or unreadable stay as they are.
bool clip_imu_row(std::vector<std::string>& fields, double t, const ImuClip& clip);

/// The shortest text that reads back to exactly `v`.
std::string shortest_text(double v);

}  // namespace sinu::test::faults
