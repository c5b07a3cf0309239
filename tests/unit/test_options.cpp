// Unit tests: the option table (hypergas/options/table.hpp) and the sampling schedule
// (hypergas/schedule.hpp): defaults agree with the engines' configurations, every value
// round-trips through its text, every range and every other-engine option is refused with
// the option's name, and the schedule is evenly spaced with its last row at `until`.
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <set>

#include "hypergas/error.hpp"
#include "hypergas/options/table.hpp"
#include "hypergas/schedule.hpp"

using namespace hypergas;
using options::RunOptions;
using registry::EngineKind;

namespace {
std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("option table: names are unique, Python spellings too", "[options]") {
  std::set<std::string> cli, py;
  for (const auto& o : options::run_table()) {
    CHECK(cli.insert(options::cli_name(o)).second);
    CHECK(py.insert(options::python_name(o)).second);
    CHECK(options::find(o.name) == &o);
    CHECK(options::find(options::python_name(o)) == &o);
    CHECK(!o.help.empty());
  }
  CHECK(options::find("no-such-option") == nullptr);
}

TEST_CASE("option table: engine defaults are the engines' Config defaults", "[options]") {
  const dsmc::Config d0 = options::dsmc_config(options::defaults(EngineKind::dsmc));
  const dsmc::Config d1;
  CHECK(d0.n == d1.n);
  CHECK(d0.seed == d1.seed);
  CHECK(d0.init == d1.init);
  CHECK(d0.vhs_exponent == d1.vhs_exponent);
  CHECK(d0.initial.kT == d1.initial.kT);
  CHECK(d0.initial.fraction == d1.initial.fraction);
  CHECK(d0.initial.mass_ratio == d1.initial.mass_ratio);
  const edmd::Config e0 = options::edmd_config(options::defaults(EngineKind::edmd));
  const edmd::Config e1;
  CHECK(e0.n == e1.n);
  CHECK(e0.seed == e1.seed);
  CHECK(e0.init == e1.init);
  CHECK(e0.packing == e1.packing);
  CHECK(e0.start_packing == e1.start_packing);
  CHECK(e0.initial.mass_ratio == e1.initial.mass_ratio);
  CHECK(registry::default_initial_state(EngineKind::dsmc) == d1.init);
  CHECK(registry::default_initial_state(EngineKind::edmd) == e1.init);
  // defaults are valid as they stand
  for (EngineKind e : {EngineKind::dsmc, EngineKind::edmd}) {
    RunOptions o = options::defaults(e);
    CHECK_NOTHROW(options::validate(o));
    CHECK(o.given.empty());
  }
}

TEST_CASE("option table: every default survives its own text and checks", "[options]") {
  for (EngineKind e : {EngineKind::dsmc, EngineKind::edmd}) {
    const RunOptions d = options::defaults(e);
    for (const auto& opt : options::run_table()) {
      if (!opt.unset.empty() || opt.required_cli) continue;  // "not given" values
      RunOptions o = options::defaults(e);
      const std::string text = options::value_text(d, opt);
      INFO(options::cli_name(opt) << " = '" << text << "'");
      options::set_text(o, opt, text);
      CHECK(options::value_text(o, opt) == text);
      CHECK(o.was_given(options::cli_name(opt)));
    }
  }
}

TEST_CASE("option table: out-of-range values are refused naming the option", "[options]") {
  for (const auto& opt : options::run_table()) {
    const std::string t(options::type_name(opt));
    if (t != "NUM" && t != "INT") continue;
    RunOptions o = options::defaults(EngineKind::dsmc);
    const double below = opt.range.lo_open ? opt.range.lo : opt.range.lo - 1.0;
    INFO(options::cli_name(opt));
    if (t == "NUM") {
      for (double bad : {below, std::nan(""), HUGE_VAL}) {
        const std::string m = message_of([&] { options::set_real(o, opt, bad); });
        CHECK(m.rfind(options::cli_name(opt) + " must be ", 0) == 0);
      }
    } else {
      const std::string m =
          message_of([&] { options::set_integer(o, opt, static_cast<long long>(below)); });
      CHECK(m.rfind(options::cli_name(opt) + " must be ", 0) == 0);
    }
    CHECK(!o.was_given(options::cli_name(opt)));
  }
  RunOptions o = options::defaults(EngineKind::dsmc);
  CHECK(message_of([&] { options::set_text(o, *options::find("n"), "10x"); }) ==
        "--n must be an integer, got '10x'");
  CHECK(message_of([&] { options::set_text(o, *options::find("model"), "nope"); })
            .rfind("--model: ", 0) == 0);
}

TEST_CASE("option table: each engine refuses the other's options", "[options]") {
  int checked = 0;
  for (const auto& opt : options::run_table()) {
    if (opt.engines == options::Engines::both) continue;
    const EngineKind other = opt.engines == options::Engines::dsmc ? EngineKind::edmd
                                                                   : EngineKind::dsmc;
    RunOptions o = options::defaults(other);
    const RunOptions d = options::defaults(opt.engines == options::Engines::dsmc
                                               ? EngineKind::dsmc
                                               : EngineKind::edmd);
    // equilibration: its default, 0, means "until / 5"
    const std::string text = opt.name == "start-packing"   ? std::string("0.05")
                             : opt.name == "equilibration" ? std::string("1")
                                                           : options::value_text(d, opt);
    options::set_text(o, opt, text);
    INFO(options::cli_name(opt));
    CHECK(message_of([&] { options::validate(o); }).rfind(options::cli_name(opt) + " applies to", 0) == 0);
    ++checked;
  }
  CHECK(checked >= 6);  // model, vhs-exponent, temperature, threads, replicas, packing, ...
}

TEST_CASE("option table: a checkpoint replays exactly the given options", "[options]") {
  RunOptions o = options::defaults(EngineKind::edmd);
  options::set_text(o, *options::find("engine"), "edmd");
  options::set_text(o, *options::find("packing"), "0.3");
  options::set_text(o, *options::find("until"), "0.1");
  options::set_text(o, *options::find("out"), "somewhere");
  options::set_flag(o, *options::find("json"), true);
  const auto a = options::replay_arguments(o);
  CHECK(a == std::vector<std::string>{"--engine", "edmd", "--until", "0.10000000000000001",
                                      "--packing", "0.29999999999999999"});
  RunOptions r = options::defaults(EngineKind::edmd);
  for (std::size_t i = 0; i < a.size(); i += 2)
    options::set_text(r, *options::find(a[i].substr(2)), a[i + 1]);
  CHECK(r.packing == o.packing);
  CHECK(r.until == o.until);
}

TEST_CASE("schedule: evenly spaced, the last row at until, every rounded", "[options]") {
  for (double until : {1.0, 10.0})
    for (double every : {0.3, 0.25, 0.7, 0.2, 1e-3}) {
      const Schedule s = Schedule::make(0.0, until, every);
      INFO("until " << until << " every " << every);
      const double k = std::max(1.0, std::round(until / every));
      CHECK(static_cast<double>(s.intervals()) == k);
      CHECK(s.every() == until / k);
      CHECK(s.time(0) == 0.0);
      CHECK(s.time(s.intervals()) == until);
      for (std::uint64_t i = 1; i < s.intervals(); ++i)
        CHECK(s.time(i) == static_cast<double>(i) * s.every());
    }
  CHECK(Schedule::make(0.0, 1.0, 0.3).rows() == 4);     // 0, 1/3, 2/3, 1
  CHECK(Schedule::make(2.0, 12.0).rows() == 51);        // without every: 50 intervals
  CHECK(Schedule::make(3.0, 3.0, 0.1).rows() == 1);     // zero span: t0 once
  CHECK(Schedule::make(0.0, 1.0, 5.0).rows() == 2);     // at least one interval
  CHECK_THROWS_AS(Schedule::make(0.0, 1.0, 1e-7), InvalidInput);  // over 1e6 rows
  CHECK_THROWS_AS(Schedule::make(1.0, 0.5, 0.1), InvalidInput);
  CHECK_THROWS_AS(Schedule::make(0.0, HUGE_VAL, 0.1), InvalidInput);
}
