// hypergas/studies/report.hpp -- error against run time (work-precision study), the code of
// `hypergas report` and bench_report.
//
//   hypergas::studies::ReportOptions o;  o.out = "report"; o.quick = true;
//   int rc = hypergas::studies::run_report(o);   // writes CSVs + work_precision.png in o.out
//
// Every error is measured against an exact value, never against another run of the code:
//   stat        DSMC hard spheres at equilibrium, D = 1..6: the time average of
//               Q = <(m |v|^2 / kT)^2> over a run of length T, against its exact
//               finite-N value (src/report_dsmc.cpp). Run time grows with T; the RMS error
//               over replicas falls as (run time)^(-1/2): the statistical regime.
//   finite_n    the same estimate for N = 200 in 3D against the Maxwell-Boltzmann value
//               D (D + 2) (<v^4> = D (D+2) (kT/m)^2): the error levels off at the finite-N
//               bias. finite_n.csv lists the bias against N for D = 2..6 with the exact
//               prediction (slope -1 in N).
//   maxwell     Maxwell molecules, D = 2..6: the relaxation rate of <|v|^4> from the delta
//               shell, fitted over 3 e-folds, against the exact (D - 1)/(2D)
//               (dsmc/maxwell_theory.hpp); run time grows with N.
//   ntc         Bird's NTC scheme, 3D hard spheres: the kurtosis <v^4>/<v^2>^2 at t = 2 from
//               the delta shell for steps dt, minus the exact scheme's value (the time-
//               continuous process; no closed form exists for hard spheres), in ntc.csv; the
//               order p of |bias| ~ dt^p is fitted where the bias exceeds 3 standard errors.
//   lanes       the lanes scheme (dsmc/detail/kac_lanes.hpp), the same kurtosis for lane
//               sizes M = 8, 64, 512, 4096 (default epoch) minus the exact scheme's, with the
//               CPU seconds per replica of both, in lanes.csv: its bias and its cost.
//   schemes     the choice of scheme: the same kurtosis at t = 2 from one run of N = 1e4,
//               1e5, 1e6 particles for the exact scheme, NTC (dt = 2 and 0.5) and lanes
//               (default lane size), in schemes.csv. The error of one run is the RMS
//               deviation of its kurtosis from the reference, the exact scheme's mean at
//               N = 1e6: sqrt(sd^2 + bias^2), the sd from the runs' scatter and bias^2
//               estimated without the noise of the two means (b^2 - se_b^2, at least 0).
//               It counts the finite-N bias with the scheme's. Run time is the CPU
//               seconds of one run. recommend() picks, for each target error E, the measured
//               point with error <= E and the least run time (schemes_recommendation).
//   eos         EDMD, N = 1000, D = 1..4: the reduced pressure Z from the collision virial
//               over a window of T time units (after the lattice has melted, t = 2), against
//                 1D rods, eta = 0.5: Tonks' exact Z = 1/(1 - eta) (L. Tonks, Phys. Rev. 50,
//                    955 (1936)); exact for any N with kT = 2 E_kin/N, so no floor. Equal
//                    rods only exchange velocities: the gas is N free points in the free
//                    length L - N sigma (integrable), the collision count of a window is
//                    fixed up to end effects, which add a 1/T term: the error falls at
//                    least as fast as T^(-1/2) (docs/benchmarks.md);
//                 2D disks, eta = 0.3: Henderson's Z = (1 + eta^2/8)/(1 - eta)^2 (Mol. Phys.
//                    30, 971 (1975); ~2e-3 from simulation);
//                 3D, eta = 0.2618: Carnahan-Starling (J. Chem. Phys. 51, 635 (1969); within
//                    ~1e-3 of simulation); CS = 3.2624: a floor from the finite-N bias
//                    plus CS's own error (the measured Z: docs/benchmarks.md);
//                 4D, x = B2 rho = 0.2 (eta = 0.025): the virial series 1 + x + (B3/B2^2) x^2,
//                    B3/B2^2 = 4/3 - 3 sqrt(3)/(2 pi) (Luban & Baram, J. Chem. Phys. 76, 3233
//                    (1982)); truncation < 0.0027 (Clisby & McCoy, J. Stat. Phys. 122, 15
//                    (2006)), a floor of ~2e-3 relative.
//               Relative RMS error over replicas; it falls as (run time)^(-1/2) until such a
//               floor. The slope is fitted over the statistical part, windows T <= 4.
//
// Run time is the CPU time of the thread that runs the replica (CLOCK_THREAD_CPUTIME_ID):
// on an idle core it equals wall-clock time, and on a shared machine it does not count the
// time the thread waited, so slopes stay meaningful. Slopes are least-squares fits of
// log10(error) against log10(run time), with their standard errors.
#pragma once

#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "hypergas/analysis/estimates.hpp"

namespace hypergas::studies {

/// What `run_report` computes and where it writes.
struct ReportOptions {
  std::string out = "report";  ///< output folder (created if missing; files replaced)
  bool quick = false;          ///< fewer points and replicas (run times: docs/benchmarks.md)
  std::uint64_t seed = 1;      ///< all randomness derives from it
  int threads = 2;             ///< replicas run on this many threads (1..64)
  bool plot = true;            ///< run gnuplot (if on PATH) to write work_precision.png
  bool verbose = true;         ///< one progress line per study on stderr
};

/// One point of a work-precision curve: relative error (RMS over replicas) of `study`
/// at control parameter `param` (run length T, N or dt), mean run time per replica (s).
struct ReportPoint {
  std::string study, engine;
  int dim = 0;
  double param = 0.0, run_s = 0.0, error = 0.0, error_se = 0.0;
  int replicas = 0;
};

/// Least-squares slope of log10(error) against log10(x) for one curve.
struct ReportSlope {
  std::string study, engine;
  int dim = 0;
  double slope = 0.0, slope_se = 0.0;
  int points = 0;
};

/// One row of a bias table (finite-N bias against N, NTC bias against dt).
struct BiasRow {
  int dim = 0;
  double param = 0.0, bias = 0.0, bias_se = 0.0, theory = 0.0;
};

/// One measured point of the scheme comparison (file comment, schemes): `scheme` is "exact",
/// "ntc" (step dt) or "lanes" (default lane size, dt 0) at n particles; error is the relative
/// RMS error of one run, error_se its standard error, run_s the CPU seconds of one run.
struct SchemePoint {
  std::string scheme;
  double dt = 0.0, n = 0.0, run_s = 0.0, error = 0.0, error_se = 0.0;
  int replicas = 0;
};

/// The scheme to use for a target relative error: the measured point with error <= target
/// and the least run_s (`found` false when no point reaches the target).
struct Recommendation {
  double target = 0.0;
  bool found = false;
  SchemePoint point;
};

/// The target errors the report recommends a scheme for.
inline constexpr double recommendation_targets[] = {1e-2, 3e-3, 1e-3, 5e-4};

/// recommend(points, target): the Recommendation for one target (ties: the first point).
Recommendation recommend(const std::vector<SchemePoint>& points, double target);

/// "exact", "ntc dt = 2", "lanes": the name of a point's scheme as the report prints it.
std::string scheme_label(const SchemePoint& p);

/// One line per target of recommendation_targets: "for relative error E within time T use
/// <scheme> (N = n; next: <scheme>, T' s at N = n')", the next being the fastest point of
/// another scheme (NTC steps count as one scheme) that reaches E, or "for relative error E:
/// no measured run reaches it"; each newline-terminated.
std::string schemes_recommendation(const std::vector<SchemePoint>& points);

/// Everything the report computes.
struct ReportResult {
  std::vector<ReportPoint> points;
  std::vector<ReportSlope> slopes;
  std::vector<BiasRow> finite_n, ntc, lanes;
  analysis::MeanSe exact_kurtosis;       ///< ntc: the exact scheme's kurtosis at t = 2
  double exact_run_s = 0.0;              ///< its thread-CPU seconds per replica
  std::vector<double> lanes_run_s;       ///< per lanes row: thread-CPU seconds per replica
  double ntc_order = std::numeric_limits<double>::quiet_NaN();  ///< p in |bias| ~ dt^p
  double ntc_order_se = std::numeric_limits<double>::quiet_NaN();
  std::vector<SchemePoint> schemes;   ///< schemes: one point per scheme and N
  analysis::MeanSe scheme_reference;  ///< schemes: the exact kurtosis at t = 2, N = 1e6
  double total_s = 0.0;  ///< wall-clock seconds of the whole study
};

/// Runs the studies of the file comment and returns their results (nothing is written).
/// Throws InvalidInput for bad options.
ReportResult run_report_study(const ReportOptions& o);

/// Writes work_precision.csv, slopes.csv, finite_n.csv, ntc.csv, lanes.csv, schemes.csv,
/// recommendation.txt, slopes.gp and
/// plot_report.gp (scripts/plot_report.gp) into `dir` and, with `plot`, runs gnuplot there
/// (work_precision.png). Each file is written to a temporary name and renamed when
/// complete. Throws InvalidInput if the folder cannot be created or written.
void write_report(const ReportResult& res, const std::filesystem::path& dir, bool plot);

/// The summary printed after a report: a table of the slopes, the NTC order (or the dt at
/// which a bias was detected) and schemes_recommendation, one line each, newline-terminated.
std::string report_summary(const ReportResult& res);

/// The bench_report entry point: runs the study, writes the files into o.out, prints
/// report_summary and the folder on stdout. Returns 0; throws InvalidInput for bad options
/// or folders.
int run_report(const ReportOptions& o);

}  // namespace hypergas::studies
