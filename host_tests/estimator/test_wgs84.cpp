// WGS-84 constants and normal gravity against published values
// (NIMA TR8350.2 tables 3.1-3.4).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <Eigen/LU>

#include "estimator/earth/wgs84.hpp"

using namespace sinu::est::wgs84;
constexpr double kDeg = std::numbers::pi / 180.0;

TEST(Wgs84, NormalGravityMatchesPublishedValues) {
  // TR8350.2: gamma_e = 9.7803253359, gamma_p = 9.8321849378 m/s^2; the
  // closed form reproduces them to the 10 digits given.
  EXPECT_NEAR(normal_gravity_m_s2(0.0, 0.0), 9.7803253359, 1e-10);
  EXPECT_NEAR(normal_gravity_m_s2(90.0 * kDeg, 0.0), 9.8321849378, 1e-9);
  // Free-air gradient near the surface is about -3.086e-6 s^-2 (TR8350.2 4-3).
  const double grad = (normal_gravity_m_s2(45 * kDeg, 100.0) - normal_gravity_m_s2(45 * kDeg, 0.0)) / 100.0;
  EXPECT_NEAR(grad, -3.086e-6, 0.005e-6);
}

TEST(Wgs84, RadiiOfCurvature) {
  EXPECT_NEAR(transverse_radius_m(0.0), kA, 1e-6);
  EXPECT_NEAR(meridian_radius_m(0.0), kA * (1 - kE2), 1e-6);               // 6 335 439.327 m
  EXPECT_NEAR(meridian_radius_m(90 * kDeg), kA / std::sqrt(1 - kE2), 1e-6);  // polar radius of curvature
  EXPECT_NEAR(transverse_radius_m(90 * kDeg), 6399593.6258, 1e-3);
}

TEST(Wgs84, EcefRoundTripIsSubMillimetre) {
  for (double lat : {-89.9, -45.0, 0.0, 30.4, 60.0, 89.9})
    for (double h : {-100.0, 0.0, 300.0, 10000.0}) {
      const auto r = geodetic_to_ecef(lat * kDeg, 114.3 * kDeg, h);
      const auto g = ecef_to_geodetic(r);
      EXPECT_NEAR(g.x(), lat * kDeg, 1e-11);  // 1e-11 rad = 0.06 mm
      EXPECT_NEAR(g.y(), 114.3 * kDeg, 1e-12);
      EXPECT_NEAR(g.z(), h, 1e-4);
    }
}

TEST(Wgs84, EarthRateAndTransportRate) {
  const double lat = 30.0 * kDeg;
  const auto w = omega_ie_n(lat);
  EXPECT_NEAR(w.norm(), kOmegaIe, 1e-18);
  EXPECT_NEAR(w.z(), -kOmegaIe * 0.5, 1e-18);  // down component = -Omega sin(lat)
  // Flying east at 40 m/s: rotation about north = v_e / (R_N + h).
  const auto rho = omega_en_n(lat, 200.0, {0.0, 40.0, 0.0});
  EXPECT_NEAR(rho.x(), 40.0 / (transverse_radius_m(lat) + 200.0), 1e-15);
  EXPECT_NEAR(rho.y(), 0.0, 1e-18);
}

TEST(Wgs84, CenIsARotationWithDownPointingInward) {
  const auto C = C_en(40 * kDeg, -105 * kDeg);
  EXPECT_NEAR((C.transpose() * C - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(C.determinant(), 1.0, 1e-15);
  const Eigen::Vector3d down_e = C.col(2);
  const Eigen::Vector3d r = geodetic_to_ecef(40 * kDeg, -105 * kDeg, 0.0);
  EXPECT_LT(down_e.dot(r.normalized()), -0.99);  // geodetic down is nearly anti-radial
}
