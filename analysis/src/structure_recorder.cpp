// g(r), g(sigma+) and S(k) of a periodic fluid (structure_recorder.hpp).
#include "hypergas/analysis/structure_recorder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <set>

#include "hypergas/analysis/estimates.hpp"
#include "hypergas/analysis/output.hpp"
#include "hypergas/error.hpp"
#include "hypergas/vec.hpp"
#include "integrals.hpp"

namespace hypergas::analysis {

namespace {

/// Volume of the unit-radius D-ball.
double ball(int d) { return std::pow(std::numbers::pi, 0.5 * d) / std::tgamma(0.5 * d + 1.0); }

/// Least-squares polynomial of degree 2 through (x, y); returns its value at 0.
double quadratic_at_zero(const std::vector<double>& x, const std::vector<double>& y) {
  // normal equations of y = a + b x + c x^2
  double s[5] = {0, 0, 0, 0, 0}, t[3] = {0, 0, 0};
  for (std::size_t i = 0; i < x.size(); ++i) {
    double p = 1.0;
    for (int k = 0; k < 5; ++k) {
      s[k] += p;
      if (k < 3) t[k] += p * y[i];
      p *= x[i];
    }
  }
  const double A[3][3] = {{s[0], s[1], s[2]}, {s[1], s[2], s[3]}, {s[2], s[3], s[4]}};
  const auto det3 = [](const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  };
  double B[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) B[i][j] = j == 0 ? t[i] : A[i][j];
  return det3(B) / det3(A);  // Cramer's rule for a
}

/// Whether m is the representative of +-m: its first non-zero component is positive.
bool half_space(const std::vector<int>& m) {
  for (int c : m)
    if (c != 0) return c > 0;
  return false;
}

}  // namespace

StructureRecorder::StructureRecorder(const StructureSettings& s, int dim, std::size_t n,
                                     double start)
    : set_(s), dim_(dim), n_(n), start_(start) {
  if (!(dim >= 1 && dim <= 6 && n >= 2 && s.dr > 0 && s.r_max > 1.0 + s.dr && s.k_max > 0 &&
        s.vectors_per_shell >= 1 && s.max_vectors >= 1 && s.centres >= 1 &&
        s.contact_bins >= 3 && s.error_blocks >= 2 &&
        std::isfinite(s.r_max) && std::isfinite(s.k_max)))
    throw InvalidInput(
        "structure: needs D in 1..6, N >= 2, dr > 0, r_max > 1 + dr, k_max > 0, >= 1 vector "
        "per shell and in all, >= 1 centre, >= 3 contact bins and >= 2 error blocks");
}

void StructureRecorder::setup(double L) {
  L_ = L;
  r_max_ = std::min(set_.r_max, 0.5 * L);
  bins_ = static_cast<std::size_t>(std::floor(r_max_ / set_.dr + 1e-9));
  if (bins_ < std::size_t(1.0 / set_.dr) + std::size_t(set_.contact_bins))
    throw InvalidInput("structure: the box (side " + std::to_string(L) +
                       ") leaves too few bins outside the core for the contact value");
  // wave-vector shells s <= |m| < s + 1, s = 1 .. M
  const double k1 = 2.0 * std::numbers::pi / L;
  const int M = static_cast<int>(std::floor(set_.k_max / k1));
  std::mt19937_64 rng(set_.seed);
  const auto cap = std::size_t(std::min(
      set_.vectors_per_shell, std::max(4, set_.max_vectors / std::max(M, 1))));
  for (int s = 1; s <= M; ++s) {
    std::vector<std::vector<int>> found;
    const double lo = double(s) * s, hi = double(s + 1) * (s + 1);
    const double cube = std::pow(2.0 * s + 3.0, dim_);
    if (cube <= 2.0e5) {  // every vector of the shell
      std::vector<int> m(std::size_t(dim_), -(s + 1));
      for (;;) {
        double m2 = 0;
        for (int c : m) m2 += double(c) * c;
        if (m2 >= lo && m2 < hi && half_space(m)) found.push_back(m);
        int a = 0;
        while (a < dim_ && ++m[std::size_t(a)] > s + 1) m[std::size_t(a++)] = -(s + 1);
        if (a == dim_) break;
      }
      std::shuffle(found.begin(), found.end(), rng);
      if (found.size() > cap) found.resize(cap);
    } else {  // random directions and radii within the shell
      std::normal_distribution<double> gauss;
      std::uniform_real_distribution<double> radius(s, s + 1);
      std::set<std::vector<int>> seen;
      for (std::size_t tries = 0; found.size() < cap && tries < 100 * cap; ++tries) {
        std::vector<double> u(static_cast<std::size_t>(dim_));
        double u2 = 0;
        for (double& x : u) x = gauss(rng), u2 += x * x;
        const double rho = radius(rng) / std::sqrt(u2);
        std::vector<int> m(static_cast<std::size_t>(dim_));
        double m2 = 0;
        for (int a = 0; a < dim_; ++a)
          m[std::size_t(a)] = static_cast<int>(std::lround(u[std::size_t(a)] * rho)), m2 += double(m[std::size_t(a)]) * m[std::size_t(a)];
        if (!(m2 >= lo && m2 < hi)) continue;
        if (!half_space(m)) for (int& c : m) c = -c;
        if (seen.insert(m).second) found.push_back(m);
      }
    }
    std::vector<int> flat;
    for (const auto& m : found) flat.insert(flat.end(), m.begin(), m.end());
    kvec_.push_back(std::move(flat));
  }
}

void StructureRecorder::observe(const Snapshot& s) {
  if (s.time < start_ - 1e-9 * std::max(1.0, std::fabs(start_))) return;
  if (finished_) throw InvalidInput("structure: observe after finish");
  if (s.dim != dim_ || s.n != n_)
    throw InvalidInput("structure: the snapshot's D or N differs from the recorder's");
  if (!s.positions || !(s.box > 0.0))
    throw InvalidInput("structure: needs positions in a periodic box (EDMD)");
  if (frames_ == 0) setup(s.box);
  const int d = dim_;
  const std::size_t stride = std::size_t(s.stride);
  const double L = L_;
  std::vector<double> x(n_ * std::size_t(d));
  for (std::size_t i = 0; i < n_; ++i)
    for (int a = 0; a < d; ++a) {
      const double p = s.positions[i * stride + std::size_t(a)];
      x[i * std::size_t(d) + std::size_t(a)] = p - L * std::floor(p / L);
    }
  // g(r): pairs counted from M centres (all particles when N <= centres, else a block of M
  // consecutive ids that moves on by M each frame) to every other particle, through cells
  // of side >= r_max with their image shifts (all particles when fewer than 3 cells fit a
  // side, with minimum images). With every particle a centre each pair is found once and
  // counts twice.
  std::vector<double> counts(bins_, 0.0);
  const double r2max = r_max_ * r_max_, inv_dr = 1.0 / set_.dr;
  const std::size_t M = std::min<std::size_t>(n_, std::size_t(set_.centres));
  const bool all = M == n_;
  const double weight = all ? 2.0 : 1.0;
  const std::size_t first = all ? 0 : (frames_ * M) % n_;
  const auto bin = [&](double r2) {
    if (r2 < r2max) {
      const auto b = static_cast<std::size_t>(std::sqrt(r2) * inv_dr);
      if (b < bins_) counts[b] += weight;
    }
  };
  const int m = static_cast<int>(std::floor(L / r_max_));
  const double half = 0.5 * L;
  if (m < 3) {
    const auto scan = [&]<int Dim>() {
      for (std::size_t c = 0; c < M; ++c) {
        const std::size_t i = (first + c) % n_;
        const double* xi = &x[i * Dim];
        // distances of a block of partners first (a loop the compiler vectorises), then bins
        constexpr std::size_t block = 256;
        double r2[block];
        for (std::size_t j0 = all ? i + 1 : 0; j0 < n_; j0 += block) {
          const std::size_t nb = std::min(block, n_ - j0);
          for (std::size_t b = 0; b < nb; ++b) {
            const double* xj = &x[(j0 + b) * Dim];
            double s2 = 0;
            for (int k = 0; k < Dim; ++k) {  // minimum image: both coordinates lie in [0, L)
              double dx = xi[k] - xj[k];
              dx = dx > half ? dx - L : dx;
              dx = dx < -half ? dx + L : dx;
              s2 += dx * dx;
            }
            r2[b] = s2;
          }
          for (std::size_t b = 0; b < nb; ++b)
            if (r2[b] < r2max && j0 + b != i) bin(r2[b]);
        }
      }
    };
    for_dim(d, [&](auto dim) { scan.template operator()<decltype(dim)::value>(); });
  } else {
    std::size_t cells = 1;
    for (int a = 0; a < d; ++a) cells *= std::size_t(m);
    std::vector<std::int64_t> head(cells, -1), next(n_, -1);
    std::vector<int> coord(n_ * std::size_t(d));
    for (std::size_t i = 0; i < n_; ++i) {
      std::size_t c = 0;
      for (int a = d - 1; a >= 0; --a) {
        int k = static_cast<int>(x[i * std::size_t(d) + std::size_t(a)] / L * m);
        k = std::min(std::max(k, 0), m - 1);
        coord[i * std::size_t(d) + std::size_t(a)] = k;
        c = c * std::size_t(m) + std::size_t(k);
      }
      next[i] = head[c];
      head[c] = static_cast<std::int64_t>(i);
    }
    std::size_t offsets = 1;
    for (int a = 0; a < d; ++a) offsets *= 3;
    for (std::size_t c0 = 0; c0 < M; ++c0) {
      const std::size_t i = (first + c0) % n_;
      const double* xi = &x[i * std::size_t(d)];
      for (std::size_t o = 0; o < offsets; ++o) {
        std::size_t c = 0, code = o;
        std::array<double, 6> shift{};
        std::array<int, 6> off{};
        for (int a = 0; a < d; ++a) off[std::size_t(a)] = int(code % 3) - 1, code /= 3;
        for (int a = d - 1; a >= 0; --a) {
          int k = coord[i * std::size_t(d) + std::size_t(a)] + off[std::size_t(a)];
          if (k < 0) k += m, shift[std::size_t(a)] = -L;
          else if (k >= m) k -= m, shift[std::size_t(a)] = L;
          c = c * std::size_t(m) + std::size_t(k);
        }
        for (std::int64_t j = head[c]; j >= 0; j = next[std::size_t(j)]) {
          if (all ? std::size_t(j) <= i : std::size_t(j) == i) continue;
          const double* xj = &x[std::size_t(j) * std::size_t(d)];
          double r2 = 0;
          for (int k = 0; k < d; ++k) {
            const double dx = xj[k] + shift[std::size_t(k)] - xi[k];
            r2 += dx * dx;
          }
          bin(r2);
        }
      }
    }
  }
  centres_ += M;
  for (double& c : counts) c /= static_cast<double>(M);  // per centre
  frames_g_.push_back(std::move(counts));
  // S(k): direct sums over the particles, exp(i k . x) as a product over the axes of
  // powers of exp(i 2 pi x_a / L), tabulated for a chunk of particles at a time
  const std::size_t shells = kvec_.size();
  std::size_t nv_all = 0;
  int mmax = 0;
  for (const auto& vs : kvec_) {
    nv_all += vs.size() / std::size_t(d);
    for (int c : vs) mmax = std::max(mmax, std::abs(c));
  }
  std::vector<double> re(nv_all, 0.0), im(nv_all, 0.0);
  constexpr std::size_t chunk = 256;
  const std::size_t W = std::size_t(mmax) + 1;
  std::vector<double> tc(chunk * std::size_t(d) * W), ts(tc.size());  // cos, sin of j theta
  for (std::size_t i0 = 0; i0 < n_; i0 += chunk) {
    const std::size_t i1 = std::min(n_, i0 + chunk);
    for (std::size_t i = i0; i < i1; ++i)
      for (int a = 0; a < d; ++a) {
        const double th = 2.0 * std::numbers::pi * x[i * std::size_t(d) + std::size_t(a)] / L;
        const double c1 = std::cos(th), s1 = std::sin(th);
        double* C = &tc[((i - i0) * std::size_t(d) + std::size_t(a)) * W];
        double* S = &ts[((i - i0) * std::size_t(d) + std::size_t(a)) * W];
        C[0] = 1.0, S[0] = 0.0;
        for (std::size_t j = 1; j < W; ++j) {
          // exact angles every 16 steps keep the recurrence's round-off small
          if (j % 16 == 0) {
            C[j] = std::cos(double(j) * th), S[j] = std::sin(double(j) * th);
          } else {
            C[j] = C[j - 1] * c1 - S[j - 1] * s1, S[j] = S[j - 1] * c1 + C[j - 1] * s1;
          }
        }
      }
    std::size_t v_all = 0;
    for (const auto& vs : kvec_) {
      const std::size_t nv = vs.size() / std::size_t(d);
      for (std::size_t v = 0; v < nv; ++v, ++v_all) {
        const int* m = &vs[v * std::size_t(d)];
        double sr = 0, si = 0;
        for (std::size_t i = i0; i < i1; ++i) {
          double pr = 1.0, pi = 0.0;
          for (int a = 0; a < d; ++a) {
            const std::size_t base = ((i - i0) * std::size_t(d) + std::size_t(a)) * W;
            const int ma = m[a];
            const double c = tc[base + std::size_t(std::abs(ma))];
            const double sn = ma < 0 ? -ts[base + std::size_t(-ma)] : ts[base + std::size_t(ma)];
            const double nr = pr * c - pi * sn;
            pi = pr * sn + pi * c, pr = nr;
          }
          sr += pr, si += pi;
        }
        re[v_all] += sr, im[v_all] += si;
      }
    }
  }
  std::vector<double> sk(shells, 0.0);
  for (std::size_t sh = 0, v_all = 0; sh < shells; ++sh) {
    const std::size_t nv = kvec_[sh].size() / std::size_t(d);
    double acc = 0.0;
    for (std::size_t v = 0; v < nv; ++v, ++v_all)
      acc += (re[v_all] * re[v_all] + im[v_all] * im[v_all]) / static_cast<double>(n_);
    sk[sh] = nv ? acc / static_cast<double>(nv) : 0.0;
  }
  frames_s_.push_back(std::move(sk));
  ++frames_;
}

const StructureResult& StructureRecorder::finish() {
  if (finished_) return result_;
  if (frames_ < 2) throw InvalidInput("structure: fewer than two snapshots: run longer");
  finished_ = true;
  const int d = dim_;
  const auto J = static_cast<std::size_t>(
      std::min<std::uint64_t>(std::uint64_t(set_.error_blocks), frames_));
  const double V = std::pow(L_, d), N = static_cast<double>(n_);
  // per centre and frame: (N - 1) / V * ball(D) (r2^D - r1^D) pairs in a shell of an ideal gas
  const double norm = 1.0 / ((N - 1.0) / V * ball(d));  // times 1 / (r2^D - r1^D)
  StructureResult& R = result_;
  R.r_max = r_max_;
  R.frames = frames_;
  // per stretch: mean counts, mean S
  const auto stretch = [&](const std::vector<std::vector<double>>& f, std::size_t j) {
    const std::size_t a = j * frames_ / J, b = (j + 1) * frames_ / J;
    std::vector<double> m(f[0].size(), 0.0);
    for (std::size_t t = a; t < b; ++t)
      for (std::size_t k = 0; k < m.size(); ++k) m[k] += f[t][k];
    for (double& v : m) v /= static_cast<double>(b - a);
    return m;
  };
  std::vector<std::vector<double>> g_j, s_j;
  for (std::size_t j = 0; j < J; ++j) {
    std::vector<double> c = stretch(frames_g_, j);
    for (std::size_t b = 0; b < bins_; ++b) {
      const double r1 = double(b) * set_.dr, r2 = r1 + set_.dr;
      c[b] *= norm / (std::pow(r2, d) - std::pow(r1, d));
    }
    g_j.push_back(std::move(c));
    s_j.push_back(stretch(frames_s_, j));
  }
  const auto mean_err = [&](const std::vector<std::vector<double>>& per, std::size_t k) {
    std::vector<double> v;
    for (const auto& p : per) v.push_back(p[k]);
    return mean_se(v);
  };
  const std::size_t core = static_cast<std::size_t>(std::lround(1.0 / set_.dr));
  std::vector<double> rbar(bins_);
  for (std::size_t b = 0; b < bins_; ++b) {
    const double r1 = double(b) * set_.dr, r2 = r1 + set_.dr;
    rbar[b] = d / (d + 1.0) * (std::pow(r2, d + 1) - std::pow(r1, d + 1)) /
              (std::pow(r2, d) - std::pow(r1, d));
    const auto [m, e] = mean_err(g_j, b);
    R.r.push_back(rbar[b]), R.g.push_back(m), R.g_error.push_back(e);
  }
  // contact value per stretch: quadratic in ln g through the first bins outside the core
  const auto contact = [&](const std::vector<double>& g) {
    std::vector<double> xs, ys;
    for (std::size_t b = core; b < core + std::size_t(set_.contact_bins); ++b) {
      if (!(g[b] > 0.0)) continue;
      xs.push_back(rbar[b] - 1.0), ys.push_back(std::log(g[b]));
    }
    return xs.size() >= 3 ? std::exp(quadratic_at_zero(xs, ys)) : 0.0;
  };
  std::vector<double> cj;
  for (const auto& g : g_j) cj.push_back(contact(g));
  R.contact = contact(R.g);
  R.contact_error = mean_se(cj).se;
  const double k1 = 2.0 * std::numbers::pi / L_;
  for (std::size_t sh = 0; sh < kvec_.size(); ++sh) {
    const std::size_t nv = kvec_[sh].size() / std::size_t(d);
    if (nv == 0) continue;
    double kk = 0;
    for (std::size_t v = 0; v < nv; ++v) {
      double m2 = 0;
      for (int a = 0; a < d; ++a) m2 += double(kvec_[sh][v * std::size_t(d) + std::size_t(a)]) * kvec_[sh][v * std::size_t(d) + std::size_t(a)];
      kk += std::sqrt(m2) * k1;
    }
    const auto [m, e] = mean_err(s_j, sh);
    R.k.push_back(kk / static_cast<double>(nv)), R.s.push_back(m), R.s_error.push_back(e);
    R.vectors.push_back(static_cast<int>(nv));
  }
  R.k_max = R.k.empty() ? 0.0 : R.k.back();
  return R;
}

void StructureRecorder::write_rdf_csv(const std::string& path) const {
  if (!finished_) throw InvalidInput("structure: results before finish()");
  std::vector<std::vector<double>> rows;
  for (std::size_t b = 0; b < result_.r.size(); ++b)
    rows.push_back({result_.r[b], result_.g[b], result_.g_error[b]});
  write_csv(path, {"r", "g", "error"}, rows);
}

void StructureRecorder::write_structure_factor_csv(const std::string& path) const {
  if (!finished_) throw InvalidInput("structure: results before finish()");
  std::vector<std::vector<double>> rows;
  for (std::size_t k = 0; k < result_.k.size(); ++k)
    rows.push_back({result_.k[k], result_.s[k], result_.s_error[k], double(result_.vectors[k])});
  write_csv(path, {"k", "S", "error", "vectors"}, rows);
}

}  // namespace hypergas::analysis
