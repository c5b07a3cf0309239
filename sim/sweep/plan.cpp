// sim/sweep/plan.cpp -- PLAN.toml (toml++) to validated cases.
#include "plan.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>

#include <fmt/core.h>
#include <toml++/toml.h>

#include "hypergas/error.hpp"
#include "hypergas/options/from_given.hpp"
#include "../engine_runs.hpp"
#include "../init_file.hpp"
#include "hypergas/options/suggest.hpp"
#include "hypergas/studies/replicas.hpp"
#include "../outputs/output.hpp"

namespace hypergas::cli::sweep {

namespace {

[[noreturn]] void bad(const std::string& msg) { throw InvalidInput(msg); }

/// "PLAN.toml line 4: ".
std::string where(const std::string& name, const toml::source_region& s) {
  return fmt::format("{} line {}", name, s.begin.line);
}

/// The entries of a table in the order they are written (toml++ keeps them sorted by key).
std::vector<std::pair<std::string, const toml::node*>> in_file_order(const toml::table& t) {
  std::vector<std::pair<std::string, const toml::node*>> v;
  for (auto&& [k, node] : t) v.emplace_back(std::string(k.str()), &node);
  std::stable_sort(v.begin(), v.end(), [&](const auto& a, const auto& b) {
    const auto& pa = t.find(a.first)->first.source().begin;
    const auto& pb = t.find(b.first)->first.source().begin;
    return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
  });
  return v;
}

/// The run option a plan key names (Python spelling only); refuses --out and --json.
const options::Option& option_of(const std::string& key, const std::string& at) {
  const options::Option* opt = options::find(key);
  if (!opt || options::python_name(*opt) != key) {
    std::string hint;
    if (opt) {
      hint = fmt::format(" (write it {})", options::python_name(*opt));
    } else {
      std::vector<std::string> keys{"replicas", "plot", "plot_x"};
      for (const options::Option& o : options::run_table()) keys.push_back(options::python_name(o));
      hint = options::did_you_mean(key, keys);
    }
    bad(fmt::format("{}: unknown option '{}'{}; a plan's keys are `hypergas run` options in "
                    "their Python spelling, and [sweep] also takes replicas, plot and plot_x",
                    at, key, hint));
  }
  if (opt->name == "out" || opt->name == "json")
    bad(fmt::format("{}: '{}' is set by the sweep (cases are written to DIR/cases/<id>)", at,
                    key));
  return *opt;
}

bool integer_option(const options::Option& opt) {
  const auto t = options::type_name(opt);
  return t == "INT" || t == "UINT";
}

/// Shortest text that reads back as the same double.
std::string number_text(double x) { return fmt::format("{}", x); }

/// One TOML value as the command-line text of `opt`.
std::string value_text(const options::Option& opt, const toml::node& v, const std::string& at) {
  const std::string_view type = options::type_name(opt);
  const std::string key = options::python_name(opt);
  if (const auto* s = v.as_string()) return s->get();  // any option: as typed on the command line
  if (type == "FLAG") {
    if (const auto* b = v.as_boolean()) return b->get() ? "true" : "false";
    bad(fmt::format("{}: {} is a flag: true or false", at, key));
  }
  if (type == "TEXT") bad(fmt::format("{}: {} takes a string (in quotes)", at, key));
  if (const auto* i = v.as_integer()) return std::to_string(i->get());
  if (const auto* d = v.as_floating_point()) {
    const double x = d->get();
    if (integer_option(opt)) {
      if (!(std::isfinite(x) && x == std::floor(x) && std::fabs(x) < 9.2e18))
        bad(fmt::format("{}: {} takes an integer, got {}", at, key, number_text(x)));
      return std::to_string(static_cast<long long>(x));
    }
    return number_text(x);
  }
  bad(fmt::format("{}: {} takes a number", at, key));
}

/// x to 15 significant digits: range values meant as decimals (0.15) lose the last bit of
/// their arithmetic (0.15000000000000002).
double round15(double x) { return std::strtod(fmt::format("{:.15g}", x).c_str(), nullptr); }

/// A number of a range table.
double range_number(const toml::table& r, const char* k, const std::string& at) {
  const toml::node* n = r.get(k);
  if (!n) bad(fmt::format("{}: the range needs `{}`", at, k));
  if (const auto* i = n->as_integer()) return static_cast<double>(i->get());
  if (const auto* d = n->as_floating_point()) return d->get();
  bad(fmt::format("{}: the range's `{}` must be a number", at, k));
}

/// The values of a range { from, to, count [, scale] } or { from, to, step }.
std::vector<std::string> range_values(const options::Option& opt, const toml::table& r,
                                      const std::string& at) {
  const std::string key = options::python_name(opt);
  for (auto&& [k, node] : r)
    if (k != "from" && k != "to" && k != "count" && k != "step" && k != "scale")
      bad(fmt::format("{}: unknown key '{}' in the range of {} (from, to, count or step, "
                      "scale)", at, k.str(), key));
  const std::string_view type = options::type_name(opt);
  if (type != "INT" && type != "UINT" && type != "NUM")
    bad(fmt::format("{}: {} is not a number; give a list", at, key));
  const double from = range_number(r, "from", at), to = range_number(r, "to", at);
  if (!std::isfinite(from) || !std::isfinite(to))
    bad(fmt::format("{}: the range of {} must have finite ends", at, key));
  const bool has_count = r.contains("count"), has_step = r.contains("step");
  if (has_count == has_step)
    bad(fmt::format("{}: the range of {} needs exactly one of count and step", at, key));
  std::string scale = "linear";
  if (const toml::node* s = r.get("scale")) {
    if (!s->as_string() || (s->as_string()->get() != "linear" && s->as_string()->get() != "log"))
      bad(fmt::format("{}: scale must be \"linear\" or \"log\"", at));
    scale = s->as_string()->get();
  }
  std::vector<double> xs;
  if (has_count) {
    const toml::node* c = r.get("count");
    if (!c->as_integer() || c->as_integer()->get() < 1 || c->as_integer()->get() > 100000)
      bad(fmt::format("{}: count must be an integer in 1..100000", at));
    const auto k = c->as_integer()->get();
    if (scale == "log" && !(from > 0 && to > 0))
      bad(fmt::format("{}: a log range needs from > 0 and to > 0", at));
    for (std::int64_t i = 0; i < k; ++i) {
      const double f = k == 1 ? 0.0 : static_cast<double>(i) / static_cast<double>(k - 1);
      double x = scale == "log" ? std::exp(std::log(from) + f * (std::log(to) - std::log(from)))
                                : (from * static_cast<double>(k - 1 - i) +
                                   to * static_cast<double>(i)) / static_cast<double>(k - 1);
      if (i == k - 1) x = to;  // the end exactly
      if (i == 0) x = from;
      xs.push_back(round15(x));
    }
  } else {
    if (scale != "linear") bad(fmt::format("{}: scale applies to count ranges only", at));
    const double step = range_number(r, "step", at);
    if (!(std::isfinite(step) && step != 0.0 && (to - from) / step >= 0.0))
      bad(fmt::format("{}: step must be non-zero and lead from `from` to `to`", at));
    const double k = std::floor((to - from) / step + 1e-9);
    if (k >= 100000) bad(fmt::format("{}: the range of {} has over 100000 values", at, key));
    for (int i = 0; i <= static_cast<int>(k); ++i) xs.push_back(round15(from + i * step));
  }
  std::vector<std::string> out;
  for (double x : xs) {
    if (integer_option(opt)) {
      const double rx = std::round(x);
      if (std::fabs(x - rx) > 1e-9 * std::max(1.0, std::fabs(x)))
        bad(fmt::format("{}: {} takes integers; the range gives {}", at, key, number_text(x)));
      out.push_back(std::to_string(static_cast<long long>(rx)));
    } else {
      out.push_back(number_text(x));
    }
  }
  return out;
}

/// The swept values of one [sweep] key: a list or a range.
std::vector<std::string> swept_values(const options::Option& opt, const toml::node& v,
                                      const std::string& at) {
  if (const auto* a = v.as_array()) {
    if (a->empty()) bad(fmt::format("{}: {} has no values", at, options::python_name(opt)));
    std::vector<std::string> out;
    for (const toml::node& e : *a) out.push_back(value_text(opt, e, at));
    return out;
  }
  if (const auto* r = v.as_table()) return range_values(opt, *r, at);
  bad(fmt::format("{}: {} in [sweep] takes a list [a, b, ...] or a range {{ from = a, to = b, "
                  "count = k }}; a single value belongs above [sweep]",
                  at, options::python_name(opt)));
}

}  // namespace

int id_width(std::size_t count) {
  int w = 1;
  for (std::size_t c = count > 0 ? count - 1 : 0; c >= 10; c /= 10) ++w;
  return std::max(4, w);
}

Plan parse_plan(const std::string& text, const std::string& name) {
  toml::table doc;
  try {
    doc = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    bad(fmt::format("{} line {}, column {}: {}", name, e.source().begin.line,
                    e.source().begin.column, e.description()));
  }
  Plan plan;
  const toml::table* sweep = nullptr;
  for (const auto& [key, node] : in_file_order(doc)) {
    const std::string at = where(name, node->source());
    if (key == "sweep") {
      sweep = node->as_table();
      if (!sweep) bad(fmt::format("{}: `sweep` must be the table [sweep]", at));
      continue;
    }
    if (node->as_table())
      bad(fmt::format("{}: unknown table [{}]; a plan has one table, [sweep]", at, key));
    const options::Option& opt = option_of(key, at);
    if (node->as_array())
      bad(fmt::format("{}: {} has a list of values; swept options belong in [sweep]", at, key));
    plan.fixed.emplace_back(&opt, value_text(opt, *node, at));
  }
  if (sweep)
    for (const auto& [key, node] : in_file_order(*sweep)) {
      const std::string at = where(name, node->source());
      if (key == "replicas") {
        const auto* i = node->as_integer();
        if (!i || i->get() < 1 || i->get() > 10000)
          bad(fmt::format("{}: replicas must be an integer in 1..10000", at));
        plan.replicas = static_cast<int>(i->get());
        continue;
      }
      if (key == "plot" || key == "plot_x") {
        const auto* s = node->as_string();
        if (!s || s->get().empty())
          bad(fmt::format("{}: {} names a column: a non-empty string", at, key));
        (key == "plot" ? plan.plot_y : plan.plot_x) = s->get();
        continue;
      }
      const options::Option& opt = option_of(key, at);
      for (const auto& [f, text] : plan.fixed)
        if (f == &opt)
          bad(fmt::format("{}: {} is both fixed and swept; give it in one place", at, key));
      plan.swept.push_back({&opt, swept_values(opt, *node, at)});
    }
  if (!plan.plot_x.empty()) {
    if (plan.plot_y.empty()) bad(fmt::format("{}: plot_x without plot", name));
    const bool found = std::any_of(plan.swept.begin(), plan.swept.end(), [&](const Swept& s) {
      return options::python_name(*s.option) == plan.plot_x;
    });
    if (!found) bad(fmt::format("{}: plot_x = \"{}\" is not a swept option", name, plan.plot_x));
  }
  if (!plan.plot_y.empty() && plan.swept.empty())
    bad(fmt::format("{}: plot needs a swept option for its x axis", name));
  return plan;
}

std::vector<Case> make_cases(const Plan& plan, const std::filesystem::path& dir) {
  std::size_t groups = 1;
  for (const Swept& s : plan.swept) {
    groups *= s.values.size();
    if (groups > 1000000) bad("the plan makes more than 1000000 cases");
  }
  const std::size_t count = groups * static_cast<std::size_t>(plan.replicas);
  if (count > 1000000) bad("the plan makes more than 1000000 cases");
  const int width = id_width(count);
  const bool checkpoints_given = std::any_of(
      plan.fixed.begin(), plan.fixed.end(), [](const auto& f) {
        return f.first->name == "checkpoint-every" || f.first->name == "checkpoint-wall";
      }) || std::any_of(plan.swept.begin(), plan.swept.end(), [](const Swept& s) {
        return s.option->name == "checkpoint-every" || s.option->name == "checkpoint-wall";
      });
  std::vector<Case> cases;
  cases.reserve(count);
  std::map<std::vector<std::string>, std::size_t> seen;  // replay arguments -> case
  for (std::size_t g = 0; g < groups; ++g) {
    std::vector<std::string> values(plan.swept.size());
    for (std::size_t j = plan.swept.size(), rest = g; j-- > 0;) {
      values[j] = plan.swept[j].values[rest % plan.swept[j].values.size()];
      rest /= plan.swept[j].values.size();
    }
    for (int r = 0; r < plan.replicas; ++r) {
      Case c;
      c.id = fmt::format("{:0{}}", cases.size(), width);
      c.group = g;
      c.replica = r;
      c.values = values;
      for (std::size_t j = 0; j < values.size(); ++j)
        c.label += fmt::format("{}{}={}", j ? " " : "", options::python_name(*plan.swept[j].option),
                               values[j]);
      if (plan.replicas > 1) c.label += fmt::format("{}replica={}", c.label.empty() ? "" : " ", r);
      try {
        // As `hypergas run` builds its options: the engine's defaults, then each option;
        // then the replica's seed, the default checkpoint and the case's folder.
        options::Given args = plan.fixed;
        for (std::size_t j = 0; j < values.size(); ++j)
          args.emplace_back(plan.swept[j].option, values[j]);
        c.options = options::from_given(args, [&](options::RunOptions& o) {
          if (r > 0) o.seed = studies::replica_seed(o.seed, r);
          if (r > 0 && !o.was_given("--seed")) o.given.push_back("--seed");
          if (!checkpoints_given && checkpointable(o))
            options::set_text(o, *options::find("checkpoint-wall"), "60s");
          options::set_text(o, *options::find("out"), (dir / "cases" / c.id).string());
          apply_init_file(o);  // a plan's init_file key: the file sets D, N (EDMD: packing)
        });
        options::validate_span(c.options, sampling_start(c.options));
      } catch (const InvalidInput& e) {
        bad(fmt::format("case {} ({}): {}", c.id, c.label.empty() ? "the only case" : c.label,
                        e.what()));
      }
      const auto [it, fresh] = seen.emplace(options::replay_arguments(c.options), cases.size());
      if (!fresh)
        bad(fmt::format("case {} ({}) repeats case {} ({}): the same options twice", c.id,
                        c.label, cases[it->second].id, cases[it->second].label));
      cases.push_back(std::move(c));
    }
  }
  return cases;
}

}  // namespace hypergas::cli::sweep
