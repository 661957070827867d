#pragma once
// `sinu calibrate` on a session (or several, one face each) held in several
// attitudes: the still parts found, the noise models fitted on the longest
// one, and the multi-position fit (six_position.hpp) on the means of all;
// its calib.json section and the printed report. A session in one attitude
// is calibrated as it always was: the whole session, no new section.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "firmware/host/calibration/calibration_run.hpp"
#include "firmware/host/calibration/six_position.hpp"
#include "firmware/host/calibration/still_segments.hpp"

namespace sinu::calibration {

/// The still parts of one loaded session (input index `input`).
struct SessionStillParts {
  std::vector<StillSegment> segments;
  std::size_t attitudes = 0;
  /// The part the noise models are fitted on: samples [begin, end).
  std::size_t noise_begin = 0, noise_end = 0;
  bool whole = true;  // one attitude (or none found): the whole session, as always
};

SessionStillParts find_still_parts(const StaticSession& session, std::size_t input,
                                   const StillDetectorConfig& detector = {});

enum class PositionsOutcome { SinglePosition, Fitted, Failed };

/// After every session is loaded and calibrated (`sessions[i]` from input i):
/// SinglePosition when the still parts of all inputs hold one attitude;
/// Fitted (filling `out`) with six or more; Failed with `why` naming the
/// problem (too few attitudes: which are there, which faces are missing).
PositionsOutcome calibrate_positions(const std::vector<SessionStillParts>& parts,
                                     const std::vector<SessionCalibration>& sessions, const GravityModel& gravity,
                                     SixPositionCalibration& out, std::string& why);

/// 1-sigma uncertainty of the mean of a still segment of `duration_s`, from the
/// axis's Allan deviation at that cluster time (log-log interpolation; below
/// the curve as white noise, beyond it flat).
double mean_sigma_from_allan(const AxisCalibration& axis, double duration_s);

/// calib.json's "six_position" section.
nlohmann::json six_position_json(const SixPositionCalibration& c);
/// The few lines `sinu calibrate` prints.
std::string six_position_report(const SixPositionCalibration& c);

}  // namespace sinu::calibration
