// Mass ratios 1e6 and 1e-6 in a two-species EDMD gas (equal diameters): no NaN or infinity,
// energy and momentum conserved to round-off, no overlap, and the cold heavy species is
// heated by the light one at the rate kinetic theory predicts for that mass ratio.
//
// Exchange rate. The energy bookkeeping of one collision is that of the DSMC test
// (test_dsmc_mass_ratio.cpp): with M = m_h + m_l, mu = m_h m_l / M, relative velocity g,
// E_h' - E_h = mu V.(g' - g), and for hard spheres E[g' | g] = (1 - kappa) g with
// kappa = 4/(D + 1), because the impact parameter is uniform over the (D-1)-disk of radius
// sigma. In a gas of hard spheres a given heavy particle meets light ones at the rate
//   n_l A chi |g|,   A = v_{D-1}(sigma) (the disk's (D-1)-volume),   n_l = N_l / L^D,
// where chi = g_hl(sigma) is the light density at contact relative to the mean (molecular
// chaos at contact: Enskog). For Maxwellian species at T_h, T_l (s2 = T_h/m_h + T_l/m_l):
//   dT_h/dt = -lambda_h (T_h - T_l),  lambda_h = 2 kappa mu n_l A chi E|g|^3 / (D M s2),
//   E|g|^3 = (2 s2)^(3/2) Gamma((D+3)/2) / Gamma(D/2),
// and lambda_l likewise with n_h; T_h - T_l decays at lambda_h + lambda_l (Landau-Teller;
// the light-heavy limit is lambda_h ~ 2 (m_l/m_h) x collision frequency).
// Contact value. The heavy particles barely move in the run (their speed is ~1e-6 of the
// light ones') and stay where the lattice start put them: to the light gas they are fixed
// obstacles, each excluding a ball of radius sigma for light centres. The light particles
// are a fluid in the free volume V_free = V - (N_h v_D(sigma) - overlaps of those balls),
// so their density away from contact is N_l / V_free, and at contact it is larger by the
// first-order excluded-volume factor of their own gas, 1 + n V_lens, V_lens the volume
// common to two balls of radius sigma whose centres are sigma apart (1 + 2.5 eta in 3D, the
// Carnahan-Starling slope). Hence n_l chi = (N_l / V_free)(1 + (N_l / V_free) V_lens). The
// obstacle term matters: n_h v_D(sigma) = 3 % (3D) to 6 % (6D) here, and a first run
// without it measured rises 2-4 % above the prediction in every D. Where two heavy
// particles are closer than 2 sigma (6D: the lattice spacing is ~1.7 sigma), part of each
// one's contact sphere lies inside the other's exclusion ball and cannot be hit; the rate
// is multiplied by the uncovered fraction of the contact surface (a 6D run without it came
// out 3-5 % below). Neglected: second order in the light density (~1e-4 relative), triple
// overlaps of exclusion balls, and the light density's structure near such pairs.
// The light density is chosen so that n_l V_lens = 1e-2: a denser gas makes these terms
// larger; a more dilute one makes cell crossings (~100 per collision at 1e-3) dominate
// the run time.
// The lattice start has no light particle near a heavy one; the run first lets the light
// ones fly a few lattice spacings (the heavy ones stay cold) and then measures.
// D = 1 is not a case of this theory, and is left out. Rods cannot pass each other: each
// light rod is caged between two heavy ones, and the light rods in a cage act as free points
// bouncing between two nearly fixed walls. A heavy rod then feels the pressure of its left
// cage minus that of its right cage, which differ by O(1) from cage to cage, so it is
// accelerated steadily (the adiabatic piston): its kinetic energy grows like t^2 from that
// mean force before the t^1 heating by collision noise that the exchange rate describes,
// and the split depends on the random cage contents, not on a rate constant.
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "extreme/extreme_common.hpp"
#include "hypergas/conserved.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/geometry.hpp"

using namespace hypergas;
using namespace hypergas::edmd;

namespace {

constexpr Features kMix{.positions = true, .species = true};

/// Volume common to two balls of radius 1 whose centres are d apart (0 <= d <= 2), in D
/// dimensions: 2 * integral_{d/2}^{1} v_{D-1}(sqrt(1 - x^2)) dx (Simpson's rule, 2000
/// intervals: relative error ~1e-12 for d = 1, the case that matters most).
double lens_volume(int D, double d = 1.0) {
  const int n = 2000;
  const double a = 0.5 * d, h = (1.0 - a) / n;
  auto f = [&](double x) { return ball_volume(D - 1, 2.0 * std::sqrt(std::max(0.0, 1.0 - x * x))); };
  double s = f(a) + f(1.0);
  for (int k = 1; k < n; ++k) s += (k % 2 ? 4.0 : 2.0) * f(a + k * h);
  return 2.0 * s * h / 3.0;
}

/// Fraction of the unit sphere's surface inside a ball of radius 1 whose centre is d away:
/// the cap of polar angle theta < arccos(d/2), measure sin^(D-2) theta (Simpson).
double cap_fraction(int D, double d) {
  const double pi = 3.14159265358979323846, t0 = std::acos(0.5 * d);
  auto integral = [&](double b) {
    const int n = 2000;
    const double h = b / n;
    auto f = [&](double t) { return std::pow(std::sin(t), D - 2); };
    double s = f(0.0) + f(b);
    for (int k = 1; k < n; ++k) s += (k % 2 ? 4.0 : 2.0) * f(k * h);
    return s * h / 3.0;
  };
  return integral(t0) / integral(pi);
}

/// Obstacle geometry of species s (exclusion balls of radius 1 = sigma for the other
/// species' centres), to pairwise overlaps, minimum image in the periodic box of side L:
/// the volume of their union, and the mean fraction of a contact sphere not covered by a
/// neighbour's exclusion ball (only the uncovered part can be hit).
struct Obstacles {
  double excluded = 0.0, open_surface = 1.0;
};
template <int D>
Obstacles obstacles(const Particles<D, kMix>& p, int s, double L) {
  std::vector<Vec<D>> x;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.species(i) == s) x.push_back(p.position(i));
  Obstacles o;
  o.excluded = static_cast<double>(x.size()) * ball_volume(D, 2.0);
  double covered = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
    for (std::size_t j = i + 1; j < x.size(); ++j) {
      Vec<D> r = x[i] - x[j];
      for (int k = 0; k < D; ++k) r[k] -= L * std::round(r[k] / L);
      const double d = r.norm();
      if (d < 2.0) {
        o.excluded -= lens_volume(D, d);
        covered += 2.0 * cap_fraction(D, d);  // one cap on each of the two spheres
      }
    }
  o.open_surface = 1.0 - covered / static_cast<double>(x.size());
  return o;
}

template <int D>
void check_exchange(double ratio) {
  const int R = 8;
  const std::size_t N = 2100;  // 6D: 4 cells per side (2000 would give 3, a stencil of every cell)
  const int heavy = ratio > 1.0 ? 1 : 0, light = 1 - heavy;
  const double m_l = heavy == 1 ? 1.0 : ratio;  // species 0 has mass 1, species 1 `ratio`
  const double vlens = lens_volume(D);
  const double n_l = 1e-2 / vlens;  // light number density: n_l V_lens = 1e-2
  Config cfg;
  cfg.n = N;
  cfg.packing = 2.0 * n_l * ball_volume(D, 1.0);  // half of the particles are light
  cfg.init = InitialState::two_temp;
  cfg.initial.mass_ratio = ratio;
  cfg.initial.fraction = 0.5;
  cfg.initial.kT_species[heavy] = 1e-6;
  cfg.initial.kT_species[light] = 1.0;
  const double A = ball_volume(D - 1, 2.0);  // v_{D-1}(sigma), sigma = 1
  const double vbar = std::sqrt(2.0 / m_l) * std::exp(std::lgamma(0.5 * (D + 1.0)) -
                                                      std::lgamma(0.5 * D));  // E|g|
  // 12 heavy-light collisions per heavy particle in the measurement (2.5e4 per replica).
  const double t_meas = 12.0 / (n_l * A * vbar);
  std::vector<double> rise(R), predicted(R);
  std::vector<int> ok(R, 0);
  extreme::for_replicas(R, [&](int r) {
    Config c = cfg;
    c.seed = 777 + 31 * D + r + (ratio > 1.0 ? 0 : 500);
    Engine<D, kMix> e(c);
    const auto& p = e.particles();
    // Let the light particles fly ~4 lattice spacings before measuring.
    const double spacing = e.box_side() / std::pow(static_cast<double>(N), 1.0 / D);
    e.run_until(4.0 * spacing / vbar);
    const double Th0 = extreme::species_temperature<D>(p, heavy);
    const double Tl0 = extreme::species_temperature<D>(p, light);
    const double mh = 1.0 / p.species_inv_mass(heavy), ml = 1.0 / p.species_inv_mass(light);
    const double M = mh + ml, mu = mh * ml / M, kappa = 4.0 / (D + 1.0);
    const double s2 = Th0 / mh + Tl0 / ml;
    const double g3 = std::pow(2.0 * s2, 1.5) *
                      std::exp(std::lgamma(0.5 * (D + 3.0)) - std::lgamma(0.5 * D));
    const double L = e.box_side(), V = std::pow(L, D);
    const double nh = 0.5 * N / V;
    const Obstacles ob = obstacles<D>(p, heavy, L);
    const double nl_free = 0.5 * N / (V - ob.excluded);
    const double nl_contact = nl_free * (1.0 + nl_free * vlens) * ob.open_surface;  // n_l chi
    const double base = 2.0 * kappa * mu * A * g3 / (D * M * s2);
    // lambda_l (light cooling) uses n_h: its size barely matters (T_h << T_l).
    const double lh = base * nl_contact, ll = base * nh, lt = lh + ll;
    predicted[r] = lh / lt * (Tl0 - Th0) * -std::expm1(-lt * t_meas);
    const auto c0 = conserved(p);
    e.run_until(e.time() + t_meas);
    const auto [de, dp] = extreme::drifts<D>(c0, conserved(p));
    rise[r] = extreme::species_temperature<D>(p, heavy) - Th0;
    bool overlap = false;
    try {
      e.check_overlaps();
    } catch (const std::logic_error&) {
      overlap = true;
    }
    ok[r] = extreme::all_finite(p) && de < 1e-12 && dp < 1e-12 && !overlap &&
            e.collisions() > N;
  });
  for (int r = 0; r < R; ++r) REQUIRE(ok[r]);
  // Student t test of the replica mean of the rise against the prediction, false-failure
  // probability 1e-4 per case (10 cases: 1e-3 in all); 0.5 % of the prediction is added
  // for the neglected terms (~1e-3) and the prediction's replica spread. Power: the
  // rise is resolved to ~1 % (se; 2.5e4 heavy-light collisions per replica, 8 replicas)
  // and the tolerance is ~7 se, so one case catches an error of ~8 % or more: a wrong kappa
  // (a factor 4/3 in 2D, 7/4 in 6D), a wrong mass dependence (orders of magnitude at these
  // ratios), a missing g(sigma). The obstacle term (3-6 %) is resolved only by the ten
  // cases together: without it all ten rises came out 1-4 % above the prediction.
  const auto [m, se] = extreme::mean_se(rise);
  const auto [pm, pse] = extreme::mean_se(predicted);
  INFO("D = " << D << ", mass ratio " << ratio << ": heavy T rise " << m << " +- " << se
              << ", kinetic theory " << pm << " +- " << pse);
  REQUIRE(std::abs(m - pm) < extreme::t_threshold(1e-4, R) * se + 3.0 * pse + 5e-3 * pm);
  REQUIRE(se < 0.03 * pm);
}

}  // namespace

TEMPLATE_TEST_CASE_SIG("EDMD hard spheres, mass ratio 1e6 and 1e-6: heating at the kinetic rate",
                       "[edmd][extreme]", ((int D), D), 2, 3, 4, 5, 6) {
  check_exchange<D>(1e6);
  check_exchange<D>(1e-6);
}
