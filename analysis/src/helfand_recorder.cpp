// Einstein-Helfand and Green-Kubo transport of the EDMD fluid (helfand_recorder.hpp).
#include "hypergas/analysis/helfand_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "hypergas/analysis/enskog.hpp"
#include "hypergas/analysis/estimates.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/error.hpp"
#include "hypergas/tally/helfand.hpp"
#include "integrals.hpp"

namespace hypergas::analysis {

namespace {

using detail::running_integral;

// correlator groups
enum Group : int {
  stress_total, stress_kinetic, stress_collisional,
  heat_total, heat_kinetic, heat_collisional,
  stress_point, heat_point, velocity, displacement
};

//// The shortest cut of every transport integral (mean free times; see finish()).
constexpr double min_cut_tau = 5.0;

// Yeh & Hummer's constant of the cubic periodic box (3D).
constexpr double xi_cubic = 2.837297;

std::vector<int> layout(int d, std::size_t tagged) {
  const int v = d * (d - 1) / 2 + (d - 1);
  std::vector<int> g;
  const auto add = [&](int group, std::size_t count) { g.insert(g.end(), count, group); };
  add(stress_total, std::size_t(v)), add(stress_kinetic, std::size_t(v));
  add(stress_collisional, std::size_t(v));
  add(heat_total, std::size_t(d)), add(heat_kinetic, std::size_t(d));
  add(heat_collisional, std::size_t(d));
  add(stress_point, std::size_t(v)), add(heat_point, std::size_t(d));
  add(velocity, tagged * std::size_t(d)), add(displacement, tagged * std::size_t(d));
  return g;
}

/// Mean square Helfand moment at every lag n from the interval averages' correlation c:
/// h^2 (n c(0) + 2 sum_{l=1}^{n-1} (n - l) c(l)).
std::vector<double> mean_square(const std::vector<double>& c, double h) {
  std::vector<double> m(c.size(), 0.0);
  // M(n+1) - M(n) = h^2 (c(0) + 2 sum_{l=1}^{n} c(l))
  double s = c[0];
  for (std::size_t n = 1; n < c.size(); ++n) {
    m[n] = m[n - 1] + h * h * s;
    s += 2.0 * c[n];
  }
  return m;
}

/// Least-squares slope of y(n h) over n in [a, b].
double slope(const std::vector<double>& y, double h, std::size_t a, std::size_t b) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0, m = 0;
  for (std::size_t n = a; n <= b && n < y.size(); ++n) {
    const double x = static_cast<double>(n) * h;
    sx += x, sy += y[n], sxx += x * x, sxy += x * y[n], m += 1;
  }
  if (m < 2) return std::numeric_limits<double>::quiet_NaN();
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

}  // namespace

HelfandRecorder::HelfandRecorder(const TransportSettings& s, int dim, std::size_t n,
                                 double start, double end)
    : set_(s), dim_(dim), n_(n), start_(start), end_(end) {
  if (!(dim >= 2 && dim <= 6 && s.tagged >= 1 && s.dt > 0 && s.max_lag > s.dt &&
        s.error_blocks >= 2 && s.window > 0 && n >= 2 && std::isfinite(start) &&
        end > start))
    throw InvalidInput(
        "helfand: needs D in 2..6, N >= 2, tagged >= 1, dt > 0, max_lag > dt, window > 0, "
        ">= 2 error blocks and end > start");
  const std::size_t t = std::min<std::size_t>(std::size_t(s.tagged), n);
  for (std::size_t k = 0; k < t; ++k) tagged_.push_back(static_cast<std::uint32_t>(k * n / t));
}

void HelfandRecorder::install(const Snapshot& s) {
  const auto stride = static_cast<std::size_t>(s.stride);
  double e2 = 0.0;
  for (std::size_t i = 0; i < n_; ++i)
    for (int a = 0; a < dim_; ++a) e2 += s.velocities[i * stride + std::size_t(a)] * s.velocities[i * stride + std::size_t(a)];
  kT_ = e2 / (dim_ * (static_cast<double>(n_) - 1.0));
  if (!(s.collisions_per_particle > 0.0 && s.time > 0.0))
    throw InvalidInput("helfand: no collisions before the recording starts: equilibrate longer");
  tau_ = s.time / s.collisions_per_particle;
  h_ = set_.dt * tau_;
  volume_ = std::pow(s.box, dim_);
  const std::size_t lags = detail::lag_count(set_.max_lag, set_.dt);
  const double span = end_ - s.time;
  const auto planned = static_cast<std::uint64_t>(std::floor(span / h_ + 1e-9));
  if (planned < 2 * lags)
    throw InvalidInput("helfand: the recording (" + std::to_string(span) +
                       " time units) is shorter than two correlation windows of " +
                       std::to_string(set_.max_lag * tau_) +
                       " (the mean free time is " + std::to_string(tau_) + "): run longer");
  corr_ = std::make_unique<BlockCorrelator>(layout(dim_, tagged_.size()), lags, planned,
                                            set_.error_blocks);
  frame_.assign(std::size_t(corr_->series()), 0.0);
  tally_ = std::make_shared<tally::Helfand>(dim_, s.time, h_, s.velocities, n_, s.stride,
                                            tagged_);
  t_first_ = s.time;
  coll_first_ = s.collisions;
}

void HelfandRecorder::request(tally::Requests& r) {
  if (!tally_ || installed_) return;
  r.set_helfand(tally_);
  installed_ = true;
}

void HelfandRecorder::observe(const Snapshot& s) {
  if (s.time < start_ - 1e-9 * std::max(1.0, std::fabs(start_))) return;
  if (!result_.empty()) throw InvalidInput("helfand: observe after finish");
  if (s.dim != dim_ || s.n != n_)
    throw InvalidInput("helfand: the snapshot's D or N differs from the recorder's");
  if (s.species || s.inv_mass)
    throw InvalidInput("helfand: one species of unit mass only (no --mass-ratio)");
  if (!s.contacts || !(s.box > 0.0))
    throw InvalidInput("helfand: the engine keeps no Helfand tally (EDMD only)");
  if (!tally_) {
    install(s);
  } else if (s.contacts->helfand != tally_) {
    throw InvalidInput(
        "helfand: the engine does not hold the recorder's tally (a restored engine, or an "
        "observer in between that does not forward request)");
  }
  tally::Helfand& H = *tally_;
  H.close_until(s.time);
  const std::vector<double>& rec = H.records();
  const int d = dim_, S = H.stress_components();
  const std::size_t R = std::size_t(H.record_size());
  const double us = 1.0 / std::sqrt(volume_ * kT_), uq = us / std::sqrt(kT_);
  for (std::size_t off = 0; off + R <= rec.size(); off += R) {
    const double* r = rec.data() + off;
    std::size_t k = 0;
    // the viscosity channels of a symmetric tensor t (S components, scale u)
    const auto channels = [&](const double* t, double u) {
      for (int a = 0; a < d; ++a)
        for (int b = a + 1; b < d; ++b) frame_[k++] = t[H.stress_index(a, b)] * u;
      for (int a = 0; a + 1 < d; ++a)
        frame_[k++] = 0.5 * (t[H.stress_index(a, a)] - t[H.stress_index(a + 1, a + 1)]) * u;
    };
    double total[27];
    for (int c = 0; c < S; ++c)
      total[c] = r[H.kinetic_stress_at() + c] + r[H.collisional_stress_at() + c];
    channels(total, us / h_);
    channels(r + H.kinetic_stress_at(), us / h_);
    channels(r + H.collisional_stress_at(), us / h_);
    for (int a = 0; a < d; ++a)
      frame_[k++] = (r[H.kinetic_heat_at() + a] + r[H.collisional_heat_at() + a]) * uq / h_;
    for (int a = 0; a < d; ++a) frame_[k++] = r[H.kinetic_heat_at() + a] * uq / h_;
    for (int a = 0; a < d; ++a) frame_[k++] = r[H.collisional_heat_at() + a] * uq / h_;
    channels(r + H.point_stress_at(), us);
    for (int a = 0; a < d; ++a) frame_[k++] = r[H.point_heat_at() + a] * uq;
    const std::size_t td = tagged_.size() * std::size_t(d);
    for (std::size_t c = 0; c < td; ++c) frame_[k++] = r[H.point_velocity_at() + int(c)];
    for (std::size_t c = 0; c < td; ++c) frame_[k++] = r[H.displacement_at() + int(c)] / h_;
    corr_->push(frame_.data());
  }
  H.clear_records();
  H.reset_kinetic(s.velocities, n_, s.stride, s.time);
  t_last_ = s.time;
  coll_last_ = s.collisions;
}

const std::vector<TransportCoefficient>& HelfandRecorder::finish() {
  if (!result_.empty()) return result_;
  if (!corr_) throw InvalidInput("helfand: no snapshot reached the recording's start");
  corr_->finish();
  if (corr_->frames() < 2 * corr_->lags())
    throw InvalidInput("helfand: " + std::to_string(corr_->frames()) +
                       " intervals, fewer than two correlation windows: run longer");
  const int d = dim_;
  const double n_density = static_cast<double>(n_) / volume_;
  const double nu =
      2.0 * static_cast<double>(coll_last_ - coll_first_) /
      (static_cast<double>(n_) * (t_last_ - t_first_));
  chi_ = nu / enskog::boltzmann_rate(d, n_density);
  phi_ = enskog::packing(d, n_density);
  const enskog::Parts fe = enskog::viscosity(d, phi_, chi_);
  const enskog::Parts fl = enskog::conductivity(d, phi_, chi_);
  const double eta0 = enskog::eta0(d), lam0 = enskog::lambda0(d);
  const double d0 = enskog::nD0(d) / n_density;
  const double kT = kT_, h = h_;
  const int J = corr_->stretches();

  // A row from its value, per-stretch values and (where the plateau rule gave them) the
  // truncation error, with its reference values.
  const auto row = [&](const char* name, double value, const std::vector<double>& st,
                       double sonine, double enskog_value, std::size_t cut, double c0,
                       double truncation) {
    TransportCoefficient r;
    r.name = name;
    r.value = value;
    r.statistical_error = mean_se(st).se;
    r.truncation_error = truncation;
    r.error = std::isfinite(truncation) ? std::hypot(r.statistical_error, truncation)
                                        : r.statistical_error;
    r.sonine = sonine;
    r.ratio = value / sonine;
    r.ratio_error = r.error / sonine;
    r.enskog = enskog_value;
    r.enskog_ratio = value / enskog_value;
    r.enskog_ratio_error = r.error / enskog_value;
    r.t_cut = static_cast<double>(cut) * h;
    r.tail = 0.0;
    r.c0 = c0;
    r.rate = r.rate_error = r.sonine_rate = std::numeric_limits<double>::quiet_NaN();
    r.stretches = st;
    result_.push_back(r);
  };
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  // The plateau rule (integrals.hpp) from min_cut_tau mean free times on (the t^(-D/2)
  // form of the tail that extrapolates the remainder holds once the collisional decay is
  // over, not within the first few collisions), to two thirds of the lags (the
  // Einstein-Helfand slope is fitted over [k_c / 2, 3 k_c / 2]).
  const std::size_t K = corr_->lags() - 1;
  const auto k_least = static_cast<std::size_t>(std::max(1.0, std::round(min_cut_tau / set_.dt)));
  // the first candidate: also at least `window` integral times of the correlation c (whose
  // running integral is I), where an exponential decay has left e^-window of it and the
  // remainder model (integrals.hpp) no longer overstates a fast decay
  const auto first_cut = [&](const std::vector<double>& c, const std::vector<double>& I) {
    return std::max(k_least, detail::auto_cut(c, I, h, set_.window));
  };
  const std::size_t k_max = 2 * K / 3;
  // Running integrals of group g to each lag k, scaled, by the trapezoid rule: of interval
  // averages (increments), whose correlation c(l) is C smoothed by a triangle of half-width
  // h, so that h (c(0)/2 + sum_{l<k} c(l) + c(k)/2) is int_0^{kh} C to O(h^2 C'') at the
  // cut and exact as k grows; of point samples, with the Euler-Maclaurin end correction at
  // 0+, h^2/12 C'(0+) (C'(0+) from the first three points; at the cut C' is negligible)
  const auto integral_of = [&](int g, bool increments, double scale) {
    const auto integral = [&](const std::vector<double>& c) {
      std::vector<double> I = running_integral(c, h);
      const double d0 = !increments && c.size() > 2
                            ? (-3.0 * c[0] + 4.0 * c[1] - c[2]) / (2.0 * h) : 0.0;
      for (std::size_t k = 1; k < I.size(); ++k) I[k] = (I[k] + h * h / 12.0 * d0) * scale;
      return I;
    };
    std::vector<std::vector<double>> Ij;
    for (int j = 0; j < J; ++j) Ij.push_back(integral(corr_->stretch_mean(g, j)));
    return std::make_pair(integral(corr_->mean(g)), std::move(Ij));
  };

  // viscosity (scale 1 / kT) and conductivity (1 / kT^2): Green-Kubo at the plateau of the
  // total flux, Einstein-Helfand around the same cut, the parts to the same cut
  const auto flux = [&](const char* base, int g_tot, int g_kin, int g_col, int g_pt,
                        double scale, double ref, const enskog::Parts& f) {
    const auto [It, Itj] = integral_of(g_tot, true, scale);
    const std::vector<double> c_tot = corr_->mean(g_tot);
    const detail::Plateau P =
        detail::plateau(It, Itj, first_cut(c_tot, running_integral(c_tot, h)), k_max, d);
    const std::size_t cut = P.cut;
    const std::size_t a = std::max<std::size_t>(1, cut / 2), b = std::min(3 * cut / 2, K);
    // the slope sees the running integral around the cut; the tail beyond it is added as
    // for Green-Kubo (from the same stretch), with the same truncation error
    const auto helfand = [&](const std::vector<double>& c, const std::vector<double>& I) {
      return 0.5 * slope(mean_square(c, h), h, a, b) * scale +
             (detail::extrapolated(I, cut, P.factor) - I[cut]);
    };
    const auto [Ik, Ikj] = integral_of(g_kin, true, scale);
    const auto [Ic, Icj] = integral_of(g_col, true, scale);
    const auto [Ip, Ipj] = integral_of(g_pt, false, scale);
    // each part to the same cut with the total's tail factor, so that the parts add up to
    // the total
    const auto part = [&](const std::vector<double>& I) {
      return detail::extrapolated(I, cut, P.factor);
    };
    const auto point = [&](const std::vector<double>&, const std::vector<double>& I) {
      return part(I);
    };
    std::vector<double> s_h, s_k, s_c, s_x, s_p;
    for (int j = 0; j < J; ++j) {
      const auto js = static_cast<std::size_t>(j);
      s_h.push_back(helfand(corr_->stretch_mean(g_tot, j), Itj[js]));
      s_k.push_back(part(Ikj[js]));
      s_c.push_back(part(Icj[js]));
      s_x.push_back(P.stretches[js] - s_k.back() - s_c.back());
      s_p.push_back(point(corr_->stretch_mean(g_pt, j), Ipj[js]));
    }
    const auto ct = corr_->mean(g_tot), ck = corr_->mean(g_kin), cc = corr_->mean(g_col);
    const auto pt = corr_->mean(g_pt);
    const std::string b0 = base;
    row(base, helfand(ct, It), s_h, ref, ref * f.total(), cut, ct[0] * scale,
        P.truncation_error);
    row((b0 + "_green_kubo").c_str(), P.value, P.stretches, ref, ref * f.total(), cut,
        ct[0] * scale, P.truncation_error);
    row((b0 + "_kinetic").c_str(), part(Ik), s_k, ref, ref * f.kinetic, cut, ck[0] * scale,
        std::fabs(part(Ik) - Ik[cut]));
    row((b0 + "_cross").c_str(), P.value - part(Ik) - part(Ic), s_x, ref, ref * f.cross, cut,
        nan, nan);
    row((b0 + "_collisional").c_str(), part(Ic), s_c, ref, ref * f.collisional, cut,
        cc[0] * scale, std::fabs(part(Ic) - Ic[cut]));
    row((b0 + "_kinetic_point").c_str(), point(pt, Ip), s_p, ref, ref * f.kinetic, cut,
        pt[0] * scale, std::fabs(part(Ip) - Ip[cut]));
    std::vector<double> norm(ct.size()), msd = mean_square(ct, h), hel(ct.size());
    for (std::size_t k = 0; k < ct.size(); ++k) {
      norm[k] = ct[k] / ct[0];
      hel[k] = k == 0 ? 0.0 : msd[k] * scale / (2.0 * static_cast<double>(k) * h);
    }
    curves_.push_back(std::move(norm));
    curves_.push_back(std::move(hel));
  };
  flux("viscosity", stress_total, stress_kinetic, stress_collisional, stress_point, 1.0 / kT,
       eta0, fe);
  flux("thermal_conductivity", heat_total, heat_kinetic, heat_collisional, heat_point,
       1.0 / (kT * kT), lam0, fl);

  // self-diffusion: Green-Kubo of the tagged velocities and Einstein from their exact
  // displacements (the slope of the mean square displacement is the displacement
  // increments' integral), each at its own plateau (the groups' correlations are per
  // component: their integrals are D_s)
  {
    const auto [Iv, Ivj] = integral_of(velocity, false, 1.0);
    const auto [Id, Idj] = integral_of(displacement, true, 1.0);
    const std::vector<double> cv0 = corr_->mean(velocity);
    const std::size_t k0 = first_cut(cv0, running_integral(cv0, h));
    const detail::Plateau Pv = detail::plateau(Iv, Ivj, k0, k_max, d);
    const detail::Plateau Pe = detail::plateau(Id, Idj, k0, k_max, d);
    const std::vector<double> cv = corr_->mean(velocity), cd = corr_->mean(displacement);
    const double de_ref = d0 * enskog::diffusion(chi_);
    row("self_diffusion", Pv.value, Pv.stretches, d0, de_ref, Pv.cut, cv[0],
        Pv.truncation_error);
    row("self_diffusion_einstein", Pe.value, Pe.stretches, d0, de_ref, Pe.cut, cd[0],
        Pe.truncation_error);
    if (d == 3) {  // the periodic box's hydrodynamic correction (Yeh & Hummer)
      const double eta = result_[0].value, L = std::cbrt(volume_);
      const double add = xi_cubic * kT / (6.0 * std::numbers::pi * eta * L);
      std::vector<double> s_yh;
      for (double x : Pe.stretches) s_yh.push_back(x + add);
      row("self_diffusion_yeh_hummer", Pe.value + add, s_yh, d0, de_ref, Pe.cut, cd[0],
          Pe.truncation_error);
    }
    std::vector<double> norm(cv.size());
    for (std::size_t k = 0; k < cv.size(); ++k) norm[k] = cv[k] / cv[0];
    curves_.push_back(std::move(norm));
  }
  return result_;
}

void HelfandRecorder::write_transport_csv(const std::string& path) const {
  if (result_.empty()) throw InvalidInput("helfand: results before finish()");
  write_transport_rows(path, result_);
}

void HelfandRecorder::write_correlations_csv(const std::string& path) const {
  if (result_.empty()) throw InvalidInput("helfand: results before finish()");
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < curves_[0].size(); ++k) {
    std::vector<double> row{static_cast<double>(k) * h_};
    for (const int c : {0, 2, 4, 1, 3}) row.push_back(curves_[std::size_t(c)][k]);
    rows.push_back(std::move(row));
  }
  write_csv(path,
            {"time", "viscosity", "thermal_conductivity", "self_diffusion", "viscosity_helfand",
             "thermal_conductivity_helfand"},
            rows);
}

}  // namespace hypergas::analysis
