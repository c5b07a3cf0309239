// hypergas/options/table.hpp -- the one table of run options. Each entry gives an option's
// name, the engines it applies to, where it is used (engine construction, the run's time
// span, the command only), its type through the RunOptions member it sets, its range, its
// unit and its help text; defaults come from defaults(engine). Everything else is derived:
// the command's CLI11 registration and --help (sim/cli_options.cpp), the other-engine check
// (validate), the arguments a checkpoint replays (replay_arguments), and the Python keyword
// arguments with their defaults and docstrings (python/src/keywords.cpp, _engines.py).
// Adding an option is one entry here, its member in RunOptions, and its use in the engine.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "hypergas/options/run_options.hpp"

namespace hypergas::options {

/// Which engines an option applies to (a bit set).
enum class Engines : unsigned char { dsmc = 1, edmd = 2, both = 3 };
/// Where an option is used: `engine` builds the engine (a keyword of hypergas.DSMC/EDMD),
/// `span` is the run's time span (a keyword of run()), `command` only the command knows.
enum class Use : unsigned char { engine, span, command };

/// The RunOptions member an option sets; its alternative is the option's type. The enum
/// members are named choices ("TEXT" to the command and Python): set from a name, printed
/// as one.
using Field = std::variant<int RunOptions::*, long long RunOptions::*, std::uint64_t RunOptions::*,
                           double RunOptions::*, std::string RunOptions::*, bool RunOptions::*,
                           registry::EngineKind RunOptions::*, dsmc::Scheme RunOptions::*,
                           dsmc::Drive RunOptions::*, dsmc::Thermostat RunOptions::*,
                           InitialState RunOptions::*>;

/// Allowed numeric values: lo .. hi, each end open or closed; NaN and inf never pass.
struct Range {
  double lo = -1e308, hi = 1e308;
  bool lo_open = false, hi_open = false;
  std::string_view must;  ///< "a finite time > 0": the message says "--until must be <must>"
};

/// Checks a text value, throwing InvalidInput that names the known values (registry
/// lookups); nullptr for free text.
using Check = void (*)(std::string_view value);
/// Help text computed from the registry or the engines (known names, jamming densities).
using Details = std::string (*)();

struct Option {
  std::string_view name;  ///< long name: "--" + name on the command line, '-' -> '_' in Python
  char short_name;        ///< one-letter alias on the command line, or 0
  Engines engines;
  Use use;
  Field field;
  Range range;            ///< numbers only
  Check check;            ///< text only (nullptr: free text)
  Details details;        ///< appended to `help` (nullptr: nothing)
  std::string_view unit;  ///< "" for numbers without a unit and for text
  std::string_view help;
  std::string_view unset;  ///< the meaning of the default where it is "not given" ("" else)
  bool initial_state;      ///< describes the initial state (not taken with given velocities)
  bool required_cli;       ///< the command refuses to run without it
};

/// Every run option, in the order of --help and of the Python signatures.
std::span<const Option> run_table();
/// The entry named `name` (without "--"; Python spelling with '_' also found), or nullptr.
const Option* find(std::string_view name);
bool applies(const Option& opt, registry::EngineKind e);
/// "--mass-ratio" and "mass_ratio".
std::string cli_name(const Option& opt);
std::string python_name(const Option& opt);
/// "INT", "UINT", "NUM", "TEXT", "FLAG".
std::string_view type_name(const Option& opt);

/// The engine of a run that does not name one.
inline constexpr registry::EngineKind default_engine = registry::EngineKind::dsmc;

/// Every option's default for engine `e`: engine parameters from dsmc::Config/edmd::Config,
/// the run's span and the command's switches from the table's own values.
RunOptions defaults(registry::EngineKind e);

/// Set `opt` in `o` and record it as given; each checks the value against the option's type,
/// range and choices and throws InvalidInput naming the option ("--n must be ...").
void set_text(RunOptions& o, const Option& opt, const std::string& text);  ///< as typed
void set_integer(RunOptions& o, const Option& opt, long long v);   ///< int and uint fields
void set_unsigned(RunOptions& o, const Option& opt, std::uint64_t v);
void set_real(RunOptions& o, const Option& opt, double v);         ///< double fields
void set_string(RunOptions& o, const Option& opt, const std::string& v);  ///< text fields
void set_flag(RunOptions& o, const Option& opt, bool v);

/// The value of `opt` in `o` as command-line text (doubles with 17 significant digits,
/// so that set_text gives the same value back).
std::string value_text(const RunOptions& o, const Option& opt);
/// The default of `opt` as --help and the docstrings show it: "10 (dsmc), 20 (edmd)" where
/// the engines differ, the `unset` meaning where there is one.
std::string default_text(const Option& opt);

/// The options a checkpoint stores and `resume` parses again: every given option except
/// --out and --json, as "--name value" pairs ("--name" alone for a flag).
std::vector<std::string> replay_arguments(const RunOptions& o);

}  // namespace hypergas::options
