#include "firmware/board/outputs/nav_log.hpp"

#include <cmath>
#include <numbers>

#include "estimator/ins/rotation.hpp"

namespace sinu::board {

namespace {
constexpr double kRadToDeg = 180.0 / std::numbers::pi;
}

std::string NavLog::header(const est::StateLayout& layout) {
  std::string h = "t,lat,lon,h,vn,ve,vd,roll,pitch,yaw,sigma_pn_m,sigma_pe_m,sigma_pd_m,sigma_vn,sigma_ve,sigma_vd,"
                  "sigma_att_n_deg,sigma_att_e_deg,sigma_att_d_deg,"
                  "err_ax,err_ay,err_az,err_gx,err_gy,err_gz,sigma_err_ax,sigma_err_ay,sigma_err_az,sigma_err_gx,"
                  "sigma_err_gy,sigma_err_gz,flags";
  for (const char* src : est::kAidingSourceNames) h += std::string(",test_ratio_") + src;
  for (std::size_t e = 0; e < est::kEffectCount; ++e) {
    if (!layout.carries(static_cast<est::Effect>(e))) continue;
    for (Eigen::Index i = 0; i < est::kEffectDims[e]; ++i) {
      const std::string component = est::effect_component_name(static_cast<est::Effect>(e), i);
      const std::string name = std::string(est::kEffectNames[e]) + (component.empty() ? "" : "_" + component);
      h += "," + name + ",sigma_" + name;
    }
  }
  return h + "\n";
}

bool NavLog::open(const std::string& path, const est::StateLayout& layout, double period_s) {
  period_s_ = period_s;
  next_write_t_ = -1e300;
  flags_ = 0;
  test_ratio_.fill(0.0);
  if (!out_.open(path)) return false;
  out_.text(header(layout));
  return true;
}

void NavLog::on_nav(const est::NavOutput& o, const est::ErrorStateFilter& filter) {
  flags_ |= o.flags;  // events between two rows are kept
  for (std::size_t i = 0; i < est::kAidingSourceCount; ++i) test_ratio_[i] = std::max(test_ratio_[i], o.test_ratio[i]);
  if (o.nav.t_s + 1e-9 < next_write_t_) return;
  write(o, filter);
  flags_ = 0;
  test_ratio_.fill(0.0);
  next_write_t_ = period_s_ > 0.0 ? std::floor(o.nav.t_s / period_s_ + 1.0 + 1e-9) * period_s_ : o.nav.t_s;
}

void NavLog::write(const est::NavOutput& o, const est::ErrorStateFilter& f) {
  const Eigen::Vector3d eul = est::euler_from_quat(o.nav.q_nb) * kRadToDeg;
  TextSink& w = out_;
  w.number(o.nav.t_s, 6);
  w.comma();
  w.number(o.nav.lat_rad * kRadToDeg, 9);
  w.comma();
  w.number(o.nav.lon_rad * kRadToDeg, 9);
  w.comma();
  w.number(o.nav.h_m, 4);
  for (Eigen::Index i = 0; i < 3; ++i) {
    w.comma();
    w.number(o.nav.v_n_m_s(i), 4);
  }
  for (Eigen::Index i = 0; i < 3; ++i) {
    w.comma();
    w.number(eul(i), 6);
  }
  for (Eigen::Index i = 0; i < 9; ++i) {
    w.comma();
    w.number(std::sqrt(o.P_nav(i, i)) * (i >= 6 ? kRadToDeg : 1.0), 6);
  }
  for (std::size_t a = 0; a < est::kSensorAxes; ++a) {
    w.comma();
    w.number(o.sensor_error[a], 9);
  }
  for (std::size_t a = 0; a < est::kSensorAxes; ++a) {
    w.comma();
    w.number(o.sensor_error_sigma[a], 9);
  }
  w.comma();
  w.number(static_cast<double>(flags_), 0);
  for (std::size_t i = 0; i < est::kAidingSourceCount; ++i) {
    w.comma();
    w.number(test_ratio_[i], 4);
  }
  for (std::size_t e = 0; e < est::kEffectCount; ++e) {
    const auto eff = static_cast<est::Effect>(e);
    if (!f.layout().carries(eff)) continue;
    for (Eigen::Index i = 0; i < est::kEffectDims[e]; ++i) {
      w.comma();  // a reserved effect not yet switched on: empty fields ("unknown")
      if (f.layout().has(eff)) w.number(f.effect(eff, i), 9);
      w.comma();
      if (f.layout().has(eff)) w.number(f.effect_sigma(eff, i), 9);
    }
  }
  w.end_row();
}

}  // namespace sinu::board
