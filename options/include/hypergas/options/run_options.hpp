// hypergas/options/run_options.hpp -- the options of one run, as plain data: what `hypergas
// run` parses, what `hypergas.DSMC`/`hypergas.EDMD` take as keywords, what a checkpoint
// replays. Their names, types, ranges, defaults, units and help live in one table
// (table.hpp); this header holds the values and the checks that involve several options.
//
// Units: DSMC time in equilibrium mean collision times, EDMD time in sigma sqrt(m/kT) with
// sigma = m = kT = 1.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "hypergas/dsmc/config.hpp"
#include "hypergas/edmd/config.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/schedule.hpp"

namespace hypergas::options {

/// The values of the run options (table.hpp names each). A valid object comes from
/// defaults(engine) and set_* (table.hpp), then validate(). A named choice (engine, scheme,
/// drive, thermostat, initial state) is held as its enum: the table parses the name once,
/// and no code past it compares option text.
struct RunOptions {
  registry::EngineKind engine = registry::EngineKind::dsmc;  ///< registry::engines
  int dim = 0;                 ///< D, 1..6
  long long n = 0;             ///< particles (signed so that negative input is caught)
  std::string out;             ///< output folder of the command
  bool json = false;           ///< the command prints summary.json's object last
  std::string model;           ///< DSMC collision model (registry::Models)
  double vhs_exponent = 0.0;   ///< VHS rate exponent a (rate ~ |g|^a)
  double restitution = 1.0;    ///< coefficient of normal restitution alpha
  dsmc::Drive drive = dsmc::Drive::none;  ///< DSMC energy input (none, white-noise)
  double drive_dt = 0.0;       ///< DSMC: interval between white-noise kicks
  double shear_rate = 0.0;     ///< uniform shear flow u_x = a y: a (0: none)
  dsmc::Thermostat thermostat = dsmc::Thermostat::none;  ///< sheared gas (none, isokinetic)
  dsmc::Scheme scheme = dsmc::Scheme::exact;  ///< DSMC time scheme (registry::schemes)
  double dt = 0.0;             ///< DSMC NTC time step
  long long lane_size = 0;     ///< DSMC lanes scheme: particles per lane (0: the default)
  double epoch = 0.0;          ///< DSMC lanes scheme: time between deals
  double tc_time = 0.0;        ///< EDMD: TC-model time (collisions this close are elastic)
  InitialState init = InitialState::maxwell;  ///< initial state (registry::initial_states)
  double until = 0.0;          ///< end time
  double every = 0.0;          ///< requested sampling interval (0: not given; Schedule)
  double histogram_every = 0.0;  ///< speed histograms this far apart (0: the final one only)
  double trajectory_every = 0.0;  ///< H5MD frames this far apart (0: no trajectory.h5)
  std::string init_file;       ///< start from this H5MD file's state ("": a generated start)
  long long init_frame = -1;   ///< the frame of init_file (negative: from the end)
  double equilibration = 0.0;  ///< EDMD: time before sampling starts (0: until / 5)
  double packing = 0.0;        ///< EDMD packing fraction eta
  double start_packing = 0.0;  ///< EDMD lattice start packing, compressed to eta (0: eta)
  double mass_ratio = 0.0;     ///< m2 / m1 of a two-mass gas (1 = one species)
  double fraction = 0.0;       ///< number fraction of the heavy species
  double temperature = 0.0;    ///< initial kT (DSMC; EDMD fixes kT = 1)
  std::uint64_t seed = 0;      ///< random seed
  int threads = 0;             ///< DSMC: threads of the one system (same result for any)
  int replicas = 0;            ///< DSMC: independent copies (seeds derived from seed)
  double checkpoint_every = 0.0;  ///< checkpoint every this much engine time (0 = off)
  std::string checkpoint_wall;    ///< checkpoint every this much wall time ("90s", "10min")
  bool transport = false;         ///< transport coefficients (both engines)
  double correlation_dt = 0.0;    ///< their sampling interval
  double correlation_time = 0.0;  ///< their longest lag
  int tagged = 0;                 ///< their tagged particles (self-diffusion)
  bool structure = false;         ///< EDMD: g(r) and S(k)
  double rdf_max = 0.0;           ///< largest r of g(r) (sigma)
  double k_max = 0.0;             ///< largest |k| of S(k) (1/sigma)
  std::vector<std::string> given;  ///< options set explicitly, as "--name", in order
  // What the command read from --init-file (not options: set by the command's
  // apply_init_file, kept in the checkpoint, written to summary.json)
  long long init_frame_read = -1;  ///< the index (0 the first) of the frame read
  std::string init_checksum;       ///< FNV-1a 64 of its positions and velocities, 16 hex digits

  /// Whether option `name` ("--packing") was set explicitly.
  bool was_given(const std::string& name) const;
  /// --checkpoint-wall in seconds (0 if not given).
  double checkpoint_wall_seconds() const;
  registry::EngineKind engine_kind() const { return engine; }
  InitialState initial_state() const { return init; }
  /// The sampling instants of the run from t0 (0 for DSMC; EDMD: the end of equilibration).
  Schedule schedule(double t0) const { return Schedule::make(t0, until, every); }
};

/// Checks what involves more than one option (each option's own range is checked when it is
/// set): the other engine's options, --vhs-exponent without --model vhs, the sampling
/// schedule, checkpoints with replicas, the packing against jamming in D, --start-packing
/// against --packing, the memory the state needs. Throws InvalidInput naming the options.
void validate(const RunOptions& o);

/// The command's checks on the sampled span from t0 (0 for DSMC, the end of the EDMD
/// equilibration) to --until, which Python's engines (whose run() takes its own span) do
/// not have: --scheme ntc with a --dt longer than the sampling interval. Throws
/// InvalidInput.
void validate_span(const RunOptions& o, double t0);
/// What the command does with the span that differs from what was asked, one line each
/// (printed as notes): an --every longer than the span (one interval), a
/// --trajectory-every or --histogram-every that is no whole number of sampling intervals
/// or does not reach --until (the spacing and the last instant used).
std::vector<std::string> span_notes(const RunOptions& o, double t0);

/// --transport samples from this time on (mean collision times): the start relaxes first.
inline constexpr double transport_warmup = 20.0;

/// EDMD --transport follows this many tagged particles (at most N) unless --tagged is
/// given: the self-diffusion's plateau needs the statistical error of the running
/// integral well below its drift (helfand_recorder.hpp); 32 (the DSMC default) leaves it
/// above.
inline constexpr int edmd_tagged = 256;

/// The engine configurations that valid options describe.
dsmc::Config dsmc_config(const RunOptions& o);
edmd::Config edmd_config(const RunOptions& o);
/// The EDMD isokinetic thermostat's interval under --thermostat isokinetic, in ideal-gas mean
/// collision times (edmd::Config::thermostat_interval).
inline constexpr double edmd_thermostat_interval = 0.1;
/// Whether the run has two species (mass_ratio != 1): the engines' Features::species.
bool two_species(const RunOptions& o);
/// The engine valid options name, for registry::with_engine (hypergas/engines.hpp): engine,
/// dimension, model, species and, for EDMD, the automatic scan at the run's packing.
registry::EngineChoice engine_choice(const RunOptions& o);

/// Largest packing fraction (exclusive) an EDMD run may ask for in D dimensions: the
/// jamming density of edmd::jamming_packing (1, 0.82, 0.64, 0.46, 0.31, 0.20 for D = 1..6).
double jamming_packing(int dim);

/// Shared single-option checks (also used by `bench`, `report` and the Python recorders):
/// throw InvalidInput naming `option`.
void check_dim(int d, const std::string& option);
void check_n(long long n, const std::string& option);
void check_threads(long long t, const std::string& option);
void check_start_packing(double start, double packing);

/// "none" / "white-noise" and the DSMC drive they name; throws InvalidInput for another
/// name.
dsmc::Drive drive_kind(std::string_view name);
std::string_view drive_name(dsmc::Drive d);
/// "none" / "isokinetic" and the thermostat they name; throws InvalidInput for another name.
dsmc::Thermostat thermostat_kind(std::string_view name);
std::string_view thermostat_name(dsmc::Thermostat t);

/// Parses the whole of `text` as a T for `option`, or throws InvalidInput naming the option
/// and the text: doubles in decimal or scientific notation (nan and inf parse; ranges refuse
/// them); signed integers also as an exact integer in scientific notation (1e6); unsigned
/// integers (seeds) as plain digits. Trailing characters (10x), hexadecimal and empty text
/// are refused.
template <class T>
T parse_number(const std::string& option, const std::string& text);

/// Parses a wall-clock duration "<number>[s|min|h]" (no unit: seconds) to seconds; throws
/// InvalidInput unless it is finite, > 0 and at most 1e9 s.
double parse_duration(const std::string& option, const std::string& text);

}  // namespace hypergas::options
