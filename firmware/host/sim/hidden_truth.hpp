#pragma once
// The hidden truth of a simulated session as JSON (schema in docs/simulation.md).
#include <nlohmann/json.hpp>

#include "firmware/host/sim/environment.hpp"
#include "firmware/host/sim/gps_receiver.hpp"
#include "firmware/host/sim/imu_error_model.hpp"

namespace sinu::sim {

nlohmann::json imu_error_model_json(const ImuErrorModel& m);
nlohmann::json gps_error_model_json(const GpsErrorModel& m);
nlohmann::json temperature_json(const TemperatureProfile& p);

}  // namespace sinu::sim
