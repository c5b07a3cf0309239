// Green-Kubo transport coefficients of the velocity-space engine (transport_recorder.hpp).
#include "hypergas/analysis/transport_recorder.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>

#include "hypergas/analysis/estimates.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/error.hpp"
#include "hypergas/tally/tally.hpp"
#include "integrals.hpp"

namespace hypergas::analysis {

using detail::cut_value;
using detail::log_slope;
using detail::running_integral;
using detail::tail_rate;

namespace {

constexpr int n_groups = 3;  // Green-Kubo integrals; group 3: displacement increments
const char* const names[n_groups + 1] = {"viscosity", "thermal_conductivity", "self_diffusion",
                                         "self_diffusion_einstein"};

std::vector<int> layout(int d, int tagged) {
  std::vector<int> g;
  for (int k = 0; k < d * (d - 1) / 2 + (d - 1); ++k) g.push_back(0);
  for (int k = 0; k < d; ++k) g.push_back(1);
  for (int k = 0; k < tagged * d; ++k) g.push_back(2);
  for (int k = 0; k < tagged * d; ++k) g.push_back(3);
  return g;
}

/// The correlator's series groups for these settings; throws InvalidInput on bad ones.
std::vector<int> series_groups(const TransportSettings& s, int dim, std::size_t n) {
  if (!(dim >= 2 && dim <= 6 && s.tagged >= 0 && s.dt > 0 && s.max_lag > s.dt &&
        s.error_blocks >= 2))
    throw InvalidInput(
        "transport: needs D in 2..6, tagged >= 0, dt > 0, max_lag > dt and >= 2 error blocks");
  return layout(dim, static_cast<int>(std::min<std::size_t>(std::size_t(s.tagged), n)));
}

}  // namespace

std::vector<double> first_sonine(const CollisionLaw& law, int d) {
  if (d < 2) throw InvalidInput("transport: no first Sonine value in D = 1");
  const double D = d, a = law.exponent;
  double eta = 0.0, ds = 0.0;
  if (law.isotropic_scattering) {
    eta = 2.0 * D * (D + 2.0) / ((D + a) * (D + a + 2.0));
    ds = 2.0 * D / (D + a);
  } else if (a == 1.0) {  // hard spheres
    eta = (D + 2.0) / 4.0;
    ds = D / 2.0;
  } else {
    throw InvalidInput("transport: no first Sonine values for hard-sphere scattering with "
                       "rate exponent " + std::to_string(a));
  }
  return {eta, D * (D + 2.0) / (2.0 * (D - 1.0)) * eta, ds};
}

double converged_over_sonine(const CollisionLaw& law, int dim, const std::string& name) {
  if (dim == 3 && !law.isotropic_scattering && law.exponent == 1.0) {
    if (name == "viscosity") return 1.016034;
    if (name == "thermal_conductivity") return 1.025218;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

TransportRecorder::TransportRecorder(const TransportSettings& s, int dim, std::size_t n,
                                     std::uint64_t frames, CollisionLaw law)
    : set_(s),
      dim_(dim),
      n_(n),
      law_(law),
      corr_(series_groups(s, dim, n), detail::lag_count(s.max_lag, s.dt), frames, s.error_blocks) {
  first_sonine(law_, dim_);  // checks the law
  const auto t = static_cast<std::size_t>(std::min<std::size_t>(std::size_t(set_.tagged), n_));
  for (std::size_t k = 0; k < t; ++k) tagged_.push_back(k * n_ / t);
  frame_.resize(std::size_t(corr_.series()));
}

void TransportRecorder::observe(const Snapshot& s) {
  if (s.time < set_.warmup - 1e-9 * std::max(1.0, set_.warmup)) return;
  if (!result_.empty()) throw InvalidInput("transport: observe after finish");
  if (s.dim != dim_ || s.n != n_)
    throw InvalidInput("transport: the snapshot's D or N differs from the recorder's");
  if (s.species || s.inv_mass)
    throw InvalidInput("transport: one species of unit mass only (no --mass-ratio)");
  if (!s.tally)
    throw InvalidInput("transport: the engine keeps no collision-level tally (DSMC only)");
  if (pending_)
    throw InvalidInput("transport: the engine did not install the fluxes asked for at the "
                       "last sample (an observer in between must forward request)");
  const auto stride = static_cast<std::size_t>(s.stride);
  if (!s.tally->fluxes) {  // the first sample (or the first after a restore): from the state
    if (kT_ == 0.0) {
      double e2 = 0.0;
      for (std::size_t i = 0; i < n_; ++i)
        for (int a = 0; a < dim_; ++a) {
          const double v = s.velocities[i * stride + std::size_t(a)];
          e2 += v * v;
        }
      kT_ = e2 / (dim_ * (static_cast<double>(n_) - 1.0));
    }
    auto f = std::make_unique<tally::Fluxes>(dim_, kT_);
    for (std::size_t i = 0; i < n_; ++i) f->add(s.velocities + i * stride, 1);
    std::vector<std::uint32_t> idx(tagged_.begin(), tagged_.end());
    f->tag(idx, n_, set_.seed);
    pending_ = std::move(f);
    last_x_.assign(tagged_.size() * std::size_t(dim_), 0.0);
  }
  const tally::Fluxes& f = pending_ ? *pending_ : *s.tally->fluxes;
  const double sn = std::sqrt(static_cast<double>(n_));
  const double us = 1.0 / (sn * kT_), uq = 1.0 / (sn * kT_ * std::sqrt(kT_));
  const double uv = 1.0 / std::sqrt(kT_);
  std::size_t k = 0;
  for (int a = 0; a < dim_; ++a)
    for (int b = a + 1; b < dim_; ++b) frame_[k++] = f.value(f.stress_index(a, b)) * us;
  for (int a = 0; a + 1 < dim_; ++a)
    frame_[k++] =
        0.5 * (f.value(f.stress_index(a, a)) - f.value(f.stress_index(a + 1, a + 1))) * us;
  for (int a = 0; a < dim_; ++a) frame_[k++] = 0.5 * f.value(f.heat_index(a)) * uq;
  for (std::size_t i : tagged_)
    for (int a = 0; a < dim_; ++a) frame_[k++] = s.velocities[i * stride + std::size_t(a)] * uv;
  // displacement increments since the previous sample (0 at the first)
  for (std::size_t t = 0; t < tagged_.size(); ++t)
    for (int a = 0; a < dim_; ++a) {
      const double x = f.displacement(t, a);
      double& last = last_x_[t * std::size_t(dim_) + std::size_t(a)];
      frame_[k++] = corr_.frames() == 0 ? 0.0 : (x - last) * uv;
      last = x;
    }
  corr_.push(frame_.data());
}

void TransportRecorder::request(tally::Requests& r) {
  if (pending_) r.set_fluxes(std::move(pending_));
}

const std::vector<TransportCoefficient>& TransportRecorder::finish() {
  if (!result_.empty()) return result_;
  corr_.finish();
  if (corr_.frames() < corr_.lags())
    throw InvalidInput("transport: " + std::to_string(corr_.frames()) +
                       " samples, fewer than the " + std::to_string(corr_.lags()) +
                       " lags of one correlation window: run longer");
  const std::vector<double> ref = first_sonine(law_, dim_);
  const double dt = set_.dt;
  const double c0_mb[n_groups] = {1.0, (dim_ + 2.0) / 2.0, 1.0};
  const int J = corr_.stretches();
  const int groups = tagged_.empty() ? 2 : n_groups;  // no tagged particles: no diffusion
  for (int g = 0; g < groups; ++g) {
    const std::vector<double> c = corr_.mean(g);
    const std::vector<double> I = running_integral(c, dt);
    const std::size_t cut = detail::auto_cut(c, I, dt, set_.window);
    const std::size_t fit_last =
        std::max<std::size_t>(2, static_cast<std::size_t>(1.5 * I[cut] / c[0] / dt));
    // one tail rate, from the whole run, for every stretch: a fit per stretch is noisy
    const double rate_tail = tail_rate(c, I, cut, dt);
    std::vector<double> vals, rates;
    for (int j = 0; j < J; ++j) {
      const std::vector<double> cj = corr_.stretch_mean(g, j);
      vals.push_back(cut_value(cj, running_integral(cj, dt), cut, dt, rate_tail).first);
      rates.push_back(log_slope(cj, dt, 0, fit_last));
    }
    TransportCoefficient r;
    r.name = names[g];
    const auto [value, tail] = cut_value(c, I, cut, dt, rate_tail);
    r.value = value;
    r.error = mean_se(vals).se;
    r.sonine = ref[std::size_t(g)];
    r.ratio = r.value / r.sonine;
    r.ratio_error = r.error / r.sonine;
    r.c0 = c[0];
    r.t_cut = static_cast<double>(cut) * dt;
    r.tail = tail;
    r.rate = log_slope(c, dt, 0, fit_last);
    r.rate_error = mean_se(rates).se;
    r.sonine_rate = c0_mb[g] / r.sonine;
    r.stretches = vals;
    r.enskog = r.sonine, r.enskog_ratio = r.ratio, r.enskog_ratio_error = r.ratio_error;
    result_.push_back(r);
    std::vector<double> norm(c.size());
    for (std::size_t k = 0; k < c.size(); ++k) norm[k] = c[k] / c[0];
    curves_.push_back(std::move(norm));
  }
  // Einstein: the mean square displacement of the tagged particles grows as 2 D_s t; with
  // exact increments d_n over the sampling intervals, its slope is
  // [C_d(0) + 2 sum_{l >= 1} C_d(l)] / dt per component (the same cut and tail rule as the
  // velocity autocorrelation, the tail of the sum geometric: C_d(k_c) q / (1 - q),
  // q = exp(-g dt))
  if (!tagged_.empty()) {
    const std::vector<double> cd = corr_.mean(3);
    const std::size_t cut = static_cast<std::size_t>(std::llround(result_[2].t_cut / dt));
    const std::vector<double> I = running_integral(cd, dt);
    const double g = tail_rate(cd, I, cut, dt);
    const double q = std::exp(-g * dt);
    const auto slope = [&](const std::vector<double>& x) {
      double sum = x[0];
      for (std::size_t l = 1; l <= cut; ++l) sum += 2.0 * x[l];
      if (g > 0.0) sum += 2.0 * x[cut] * q / (1.0 - q);  // sum_{l > k_c} of C_d(k_c) q^(l - k_c)
      return sum / (2.0 * dt);
    };
    std::vector<double> vals;
    for (int j = 0; j < J; ++j) vals.push_back(slope(corr_.stretch_mean(3, j)));
    TransportCoefficient r;
    r.name = names[3];
    r.value = slope(cd);
    r.error = mean_se(vals).se;
    r.sonine = ref[2];
    r.ratio = r.value / r.sonine;
    r.ratio_error = r.error / r.sonine;
    r.c0 = cd[0];
    r.t_cut = static_cast<double>(cut) * dt;
    r.tail = g > 0.0 ? cd[cut] * q / (1.0 - q) / dt : 0.0;
    r.rate = r.rate_error = r.sonine_rate = std::numeric_limits<double>::quiet_NaN();
    r.stretches = vals;
    r.enskog = r.sonine, r.enskog_ratio = r.ratio, r.enskog_ratio_error = r.ratio_error;
    result_.push_back(r);
  }
  return result_;
}

std::vector<double> TransportRecorder::normalised(int g) const {
  if (curves_.empty()) throw InvalidInput("transport: results before finish()");
  return curves_.at(std::size_t(g));
}

void write_transport_rows(const std::string& path, const std::vector<TransportCoefficient>& rows) {
  write_file_atomic(path, [&](std::ostream& o) {
    o << "coefficient,value,error,first_sonine,ratio,ratio_error,t_cut,tail,c0,decay_rate,"
         "decay_rate_error,first_sonine_rate,enskog,enskog_ratio,enskog_ratio_error,"
         "statistical_error,truncation_error\n";
    o << std::setprecision(17);
    for (const auto& r : rows) {
      o << r.name;
      for (double x : {r.value, r.error, r.sonine, r.ratio, r.ratio_error, r.t_cut, r.tail,
                       r.c0, r.rate, r.rate_error, r.sonine_rate, r.enskog, r.enskog_ratio,
                       r.enskog_ratio_error, r.statistical_error, r.truncation_error}) {
        o << ',';
        if (std::isfinite(x)) o << x;
      }
      o << '\n';
    }
  });
}

void TransportRecorder::write_transport_csv(const std::string& path) const {
  if (result_.empty()) throw InvalidInput("transport: results before finish()");
  write_transport_rows(path, result_);
}

void TransportRecorder::write_correlations_csv(const std::string& path) const {
  if (result_.empty()) throw InvalidInput("transport: results before finish()");
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < curves_[0].size(); ++k) {
    const double t = static_cast<double>(k) * set_.dt;
    std::vector<double> row{t};
    for (int g = 0; g < n_groups; ++g) {  // no tagged particles: the last two columns empty
      const bool has = std::size_t(g) < curves_.size();
      const double nan = std::numeric_limits<double>::quiet_NaN();
      row.push_back(has ? curves_[std::size_t(g)][k] : nan);
      row.push_back(has ? std::exp(-t * result_[std::size_t(g)].sonine_rate) : nan);
    }
    rows.push_back(std::move(row));
  }
  write_csv(path,
            {"time", "viscosity", "viscosity_sonine", "thermal_conductivity",
             "thermal_conductivity_sonine", "self_diffusion", "self_diffusion_sonine"},
            rows);
}

}  // namespace hypergas::analysis
