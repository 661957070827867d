#pragma once
// Initial alignment: the first attitude, position and velocity of the INS,
// and how uncertain they are. No rest period is required.
//   Tilt: levelled at rest (rest_levelling.hpp) and carried by the gyros
//     from the end of the rest period; without a rest (a start in motion, a
//     reboot in the air) from the in-motion alignment (in_motion_alignment.hpp,
//     gravity and GNSS velocity over a few seconds).
//   Heading, in order of preference:
//     - at rest, the magnetometer, as soon as there is a fix: with the site's
//       declination (sigma a few deg), given, or else from the World Magnetic
//       Model at the fix's position and date when the field the sensor
//       measures is the Earth's (its strength and dip within
//       geomag_max_field_ratio / geomag_max_dip_rad of the model's; a fix
//       without a date takes the model's mid-span, the declination's drift
//       over the span in the sigma). A field the model does
//       not recognise (bent by an uncalibrated hard iron of tens of uT, a
//       local anomaly) may point anywhere: no heading from it; the alignment
//       waits for the GNSS motion as without a magnetometer;
//     - in motion, the in-motion alignment's own heading once the velocity
//       has changed enough to show it; else the magnetometer, as a
//       measurement of the in-motion attitude (field_heading_update.hpp: in a
//       steady acceleration it also gives the tilt the velocity cannot);
//       else, after course_wait_s of tilt without either, the GNSS course;
//     - at rest without a magnetometer, the GNSS course once the speed
//       passes min_course_speed_m_s (sigma covers crab and sideslip); from
//       differenced fixes when the receiver sends no velocity
//       (position_velocity.hpp).
// A rest window the GNSS contradicts (a fix at rest_contradicted_m_s or
// faster while it lasts, or after it with no still fix since it began) was a
// steady acceleration (rest_levelling.hpp): the levelling goes back to the
// rest of the last still fix, its attitude carried by the gyros since, or,
// with no still fix yet, to none (the in-motion alignment takes over).
// The course is the heading only if the unit's x axis points along the
// track: a unit mounted turned, a multirotor flying sideways or backwards
// gives a course any angle off, stated with a sigma of a few degrees. So
// after a course alignment the in-motion alignment keeps running (up to
// course_check_s) until its own yaw is informative (course_check_sigma_rad,
// ~5 s of driving), and check_course hands each such yaw to the navigator,
// which ends the check when the two agree and turns the solution when they
// disagree (the real drive turned 90 deg on its mount: 37.7 -> 3.4 m over
// ten outages; docs/experiments.md).
// Status: WaitingForRest (no tilt yet), Levelled (tilt known, waiting for a
// heading), Aligned.
#include <cmath>
#include <cstdint>

#include "estimator/align/in_motion_alignment.hpp"
#include "estimator/align/position_velocity.hpp"
#include "estimator/align/rest_levelling.hpp"
#include "estimator/ekf/aiding/gnss_observation.hpp"
#include "estimator/ins/imu_sample.hpp"
#include "estimator/ins/nav_state.hpp"

namespace sinu::est {

enum class AlignStatus { WaitingForRest, Levelled, Aligned };

struct AlignmentConfig {
  RestConfig rest;
  InMotionAlignmentConfig in_motion;
  PositionVelocityConfig position_velocity;  // a receiver without velocity sentences
  double course_wait_s = 5.0;              // in motion, no heading from the velocity change: the course after this
  double min_course_speed_m_s = 3.0;       // course from a GNSS receiver is unreliable below walking speed
  double course_heading_sigma_rad = 0.15;  // heading minus course: crab in wind, a car's sideslip
  bool use_mag = true;                     // heading from the magnetometer at rest when there is one
  bool declination_known = false;
  double mag_declination_rad = 0.0;        // east of true north positive (used when known)
  double mag_heading_sigma_rad = 0.05;     // with the declination: its model error, residual hard iron
  // The field's error behind a magnetic heading: hard iron left after calibration, a local anomaly. The
  // heading error it makes is this over the horizontal field: 2 deg at 30 uT, 18 deg at 3 uT near a
  // magnetic pole, where mag_heading_sigma_rad alone would claim too much.
  double mag_residual_field_uT = 1.0;
  double mag_unknown_declination_sigma_rad = 0.35;  // without it: |declination| < 20 deg at most sites
  // The World Magnetic Model's declination when none is given and the fix has a date.
  bool use_geomagnetic_model = true;
  double geomag_max_field_ratio = 0.15;    // | |m| / F_model - 1 |: residual hard iron, local anomaly
  double geomag_max_dip_rad = 0.087;       // 5 deg between the measured and the model's inclination
  double climb_sigma_m_s = 3.0;            // vertical velocity aligned in motion: NMEA has none
  double rest_contradicted_m_s = 1.0;      // a fix this fast: not at rest (a receiver at rest reads < 0.3)
  // After a heading from the GNSS course: how long the in-motion alignment keeps running to check it, the
  // yaw sigma at which its yaw is sure enough to (20 deg: tells a course 90 deg off the heading), and how
  // long it must contradict the filter's (the EKF may still be turning to it on its own).
  double course_check_s = 120.0;
  double course_check_sigma_rad = 0.35;
  double course_check_persist_s = 2.0;
};

/// Where the first heading came from (AlignmentResult, the replay's summary).
enum class HeadingSource : std::uint8_t {
  MagnetometerGivenDeclination,  // the magnetometer with the configured declination
  MagnetometerModelDeclination,  // the magnetometer with the World Magnetic Model's declination
  MagnetometerUndatedModel,      // the same without a date: the model's mid-span, its drift in the sigma
  MagnetometerNoDeclination,     // the magnetometer, declination unknown (wide sigma)
  InMotion,                      // the in-motion alignment's velocity-change fit
  GnssCourse,                    // the GNSS course
};
inline constexpr const char* heading_source_name(HeadingSource s) {
  switch (s) {
    case HeadingSource::MagnetometerGivenDeclination: return "magnetometer, given declination";
    case HeadingSource::MagnetometerModelDeclination: return "magnetometer, World Magnetic Model declination";
    case HeadingSource::MagnetometerUndatedModel:
      return "magnetometer, World Magnetic Model declination (no date: the model's 2015-2030 span)";
    case HeadingSource::MagnetometerNoDeclination: return "magnetometer, declination unknown";
    case HeadingSource::InMotion: return "in-motion alignment (velocity change)";
    case HeadingSource::GnssCourse: return "GNSS course";
  }
  return "?";
}

/// Why the course check turns a heading (check_course), as the programs say it.
inline constexpr const char* kCourseTurnedCause =
    "the unit's x axis is not along the track: mounted turned, or moving sideways";

/// What a restart did with the turn-on biases it saved (estimator/nav/warm_start.hpp checked_by_the_rest).
enum class SavedBiases : std::uint8_t { None, Kept, Moved };

struct AlignmentResult {
  NavState nav;
  Eigen::Vector3d att_sigma_rad{0.02, 0.02, 0.1};  // tilt about north, east; yaw
  Eigen::Vector3d vel_sigma_m_s{0.5, 0.5, 0.5};    // NED (in motion: NMEA has no vertical velocity)
  bool at_rest = false;                             // levelled at rest: the fields below hold
  Eigen::Vector3d rest_specific_force_b_m_s2 = Eigen::Vector3d::Zero();  // rest window mean
  double rest_specific_force_sigma_m_s2 = 0.0;      // standard error of that mean
  Eigen::Vector3d gyro_bias_rad_s = Eigen::Vector3d::Zero();  // mean rate at rest minus Earth rate
  double gyro_bias_sigma_rad_s = 0.0;
  double temp_ref_degC = 0.0;
  HeadingSource heading_source = HeadingSource::GnssCourse;
  // A course heading the in-motion alignment contradicted later (check_course): the turn the
  // navigator gave the solution [rad] and when (NaN: not turned, or no course heading).
  double course_turn_rad = NAN, course_turn_t_s = NAN;
  double declination_rad = NAN;   // the declination used (magnetometer headings with one)
  double declination_drift_rad = 0.0;  // without a date: its change to either end of the model's span
  // The field at rest was read through a restart's saved iron
  // (set_saved_iron_field), which made it the Earth's: the navigator then
  // carries that iron.
  bool field_corrected_by_saved_iron = false;
  // A restart's saved iron was tried and did not make the field the Earth's:
  // aligned on the field as read, or not aligned when that fails too.
  bool saved_iron_refused = false;
  // A restart's saved turn-on biases at a rest alignment (the navigator's
  // keep_saved_biases): none offered, kept, or moved since the save.
  SavedBiases saved_biases = SavedBiases::None;
  // The measured field against the model's, when the model was consulted:
  // its strength ratio and dip difference (why it was or was not used).
  double field_ratio = NAN, dip_difference_rad = NAN;
  // The model's Earth field at the fix (NED), whether or not the measured field
  // matched it (NaN with the model switched off): the strength and dip the
  // navigator's field states start from (aiding/field_model).
  Eigen::Vector3d model_field_n_uT = Eigen::Vector3d::Constant(NAN);
};

class CoarseAlignment {
 public:
  void configure(const AlignmentConfig& cfg);
  /// One IMU sample, dt since the previous one.
  void add_imu(const ImuSample& s, double dt_s);
  /// A GNSS epoch valid at the current IMU instant t_now_s; true (and `out`
  /// filled) when it completes the alignment.
  bool add_gnss(const GnssObservation& z, double t_now_s, AlignmentResult& out);
  AlignStatus status() const { return status_; }
  /// After a course alignment, with each GNSS epoch: true when the in-motion
  /// alignment's yaw [rad] at t_now_s is informative (`yaw_rad`, `sigma_rad`),
  /// until end_course_check() or course_check_s after the alignment.
  bool check_course(const GnssObservation& z, double t_now_s, double& yaw_rad, double& sigma_rad);
  bool checking_course() const { return course_check_until_s_ > 0.0; }
  /// The last field check against the model (NaN before any): the strength
  /// ratio and the dip difference [rad], also when they refused the field.
  double field_ratio() const { return field_ratio_; }
  double dip_difference_rad() const { return dip_difference_rad_; }
  /// The last field check tried the restart's saved iron, which did not make the field the Earth's.
  bool saved_iron_refused() const { return saved_iron_refused_; }
  void end_course_check() { course_check_until_s_ = -1.0; }
  /// A restart's saved magnetometer iron as the first reading of the field at
  /// rest, taken where it makes the field the Earth's (else the field as
  /// corrected now): the rest's mean field becomes A m + b (the saved iron's
  /// correction of what the current one gave). Only at rest: in motion the
  /// GNSS gives the heading.
  void set_saved_iron_field(const Eigen::Matrix3d& A, const Eigen::Vector3d& b) {
    saved_iron_A_ = A;
    saved_iron_b_ = b;
    have_saved_iron_ = true;
  }

 private:
  void finish(const GnssObservation& z, double t_now_s, double turn_rad, double yaw_sigma_rad, AlignmentResult& out);
  bool align_in_motion(const GnssObservation& z, double t_now_s, AlignmentResult& out);
  void finish_in_motion(const GnssObservation& z, double t_now_s, const InMotionSolution& s, double yaw_rad,
                        double yaw_sigma_rad, AlignmentResult& out);
  /// The in-motion solution `s` updated with the last magnetometer sample's
  /// heading (field_heading_update.hpp), when the field is the Earth's at the
  /// updated tilt (field_recognised): true, `s` and the heading's source in `out`.
  bool with_field_heading(const GnssObservation& z, InMotionSolution& s, AlignmentResult& out);
  /// A magnetic heading's sigma from the field alone: the residual field and the
  /// vertical field the tilt's error turns into the horizontal, over the horizontal field.
  double field_heading_sigma(const Eigen::Vector3d& m_level_uT, double tilt_sigma_rad) const;
  /// The levelled attitude's tilt sigma: the levelling's noise and the gyros' since the rest.
  double rest_tilt_sigma() const;
  /// A fix's speed against the rest windows since the last still fix (see the header).
  void check_rest(const GnssObservation& z);
  /// The declination at the fix z: given, or the model's (without a date, at
  /// the middle of its span, its drift to either end in the sigma), or none
  /// (0, wide sigma) with the model switched off; with the model's field
  /// strength and inclination there when it was consulted (NaN otherwise).
  struct FieldDeclination {
    double rad = 0.0, sigma_rad = 0.0, drift_rad = 0.0;
    HeadingSource source = HeadingSource::MagnetometerNoDeclination;
    double model_total_uT = NAN, model_inclination_rad = NAN;
  };
  FieldDeclination declination_at(const GnssObservation& z) const;
  /// Whether a field measured in the levelled frame is the Earth's as the
  /// model has it where `d` was taken (strength and dip; recorded for the
  /// result). False: its heading may be off by any angle. True when the model
  /// was not consulted.
  bool field_recognised(const Eigen::Vector3d& m_level_uT, const FieldDeclination& d);
  /// The declination's source and value into the result.
  void use_declination(const FieldDeclination& d, AlignmentResult& out) const;
  /// The last field check against the model (NaN: none), kept for the result
  /// whichever source the heading finally came from.
  void record_field_check(const GnssObservation& z, AlignmentResult& out) const;

  AlignmentConfig cfg_;
  AlignStatus status_ = AlignStatus::WaitingForRest;
  RestLevelling rest_;
  InMotionAlignment in_motion_;
  PositionVelocity position_velocity_;
  Eigen::Vector3d last_mag_b_uT_ = Eigen::Vector3d::Zero();
  bool have_mag_ = false;
  double last_temp_degC_ = 0.0;
  double tilt_since_s_ = -1.0;  // first in-motion solution with a good tilt (-1: none yet)
  double course_check_until_s_ = -1.0;  // aligned on the course: the check runs until then (-1: no check)
  /// Aligned: the check starts when the heading is the course.
  void aligned(const AlignmentResult& out, double t_now_s);
  Eigen::Quaterniond q_now_ = Eigen::Quaterniond::Identity();  // rest attitude (yaw 0) carried by the gyros
  double carried_s_ = 0.0;                                      // since the end of the rest
  // The rest as the last still fix saw it, and its attitude carried since.
  bool have_still_ = false;
  RestEstimate still_rest_;
  long still_windows_ = 0;
  Eigen::Quaterniond q_still_ = Eigen::Quaterniond::Identity();
  double carried_still_s_ = 0.0;
  double field_ratio_ = NAN, dip_difference_rad_ = NAN;         // the last field check against the model
  bool have_saved_iron_ = false;  // set_saved_iron_field
  bool saved_iron_refused_ = false;
  Eigen::Matrix3d saved_iron_A_ = Eigen::Matrix3d::Identity();
  Eigen::Vector3d saved_iron_b_ = Eigen::Vector3d::Zero();
  /// The rest's field in the levelled frame, as the Earth's if it is (out's flag set when only the saved iron makes it so).
  bool rest_field(const RestEstimate& r, const FieldDeclination& d, Eigen::Vector3d& m_level, AlignmentResult& out);
};

}  // namespace sinu::est
