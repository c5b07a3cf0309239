// python/src/keywords.cpp -- keyword arguments -> options::RunOptions through the option
// table, and the table and the sampling schedule for the Python package (keywords.hpp).
#include "keywords.hpp"

#include <pybind11/stl.h>

#include <algorithm>

#include "convert.hpp"
#include "hypergas/options/from_given.hpp"
#include "hypergas/options/suggest.hpp"
#include "hypergas/schedule.hpp"

namespace hypergas::python {

namespace {
/// Sets `opt` from a Python value, converted by the option's type.
void set_value(options::RunOptions& o, const options::Option& opt, const py::handle& value) {
  const std::string k = options::python_name(opt);
  const std::string_view t = options::type_name(opt);
  if (t == "NUM") options::set_real(o, opt, as_real(k, value));
  else if (t == "UINT") options::set_unsigned(o, opt, as_seed(value));
  else if (t == "TEXT") options::set_string(o, opt, as_text(k, value));
  else if (t == "FLAG") {
    if (!PyBool_Check(value.ptr())) type_error(k + " must be True or False");
    options::set_flag(o, opt, value.cast<bool>());
  } else {
    options::set_integer(o, opt, as_integer(k, value));
  }
}

py::object python_value(const options::RunOptions& o, const options::Option& opt) {
  return std::visit(
      [&](auto m) -> py::object {
        using T = std::remove_reference_t<decltype(o.*m)>;
        if constexpr (std::is_enum_v<T> || std::is_same_v<T, InitialState>)
          return py::cast(options::value_text(o, opt));  // a named choice: its name
        else
          return py::cast(o.*m);
      },
      opt.field);
}

const char* use_name(options::Use u) {
  switch (u) {
    case options::Use::engine: return "engine";
    case options::Use::span: return "span";
    default: return "command";
  }
}
}  // namespace

std::vector<std::string> engine_keywords(registry::EngineKind kind, bool given_velocities) {
  std::vector<std::string> k;
  for (const options::Option& opt : options::run_table()) {
    if (opt.use != options::Use::engine || !options::applies(opt, kind)) continue;
    if (given_velocities && (opt.initial_state || opt.name == "dim" || opt.name == "n"))
      continue;
    k.push_back(options::python_name(opt));
  }
  return k;
}

options::RunOptions run_options(registry::EngineKind kind, const py::kwargs& kw,
                                const std::vector<std::string>& allowed,
                                const std::function<void(options::RunOptions&)>& adjust) {
  return options::make(kind, [&](options::RunOptions& o) {
    for (const auto& [key, value] : kw) {
      const std::string k = py::str(key);
      if (std::find(allowed.begin(), allowed.end(), k) == allowed.end())
        type_error("unexpected keyword argument '" + k + "'" + options::did_you_mean(k, allowed));
      if (value.is_none()) continue;  // not given: the default
      set_value(o, *options::find(k), value);
    }
    if (adjust) adjust(o);
  });
}

void bind_options(py::module_& m) {
  m.def("did_you_mean",
        [](const std::string& name, const std::vector<std::string>& candidates) {
          return options::did_you_mean(name, candidates);
        },
        "\"; did you mean 'X'?\" for the candidate nearest a misspelt name, or \"\" "
        "(the command's rule, hypergas/options/suggest.hpp).");
  m.def("option_table", [] {
    py::list rows;
    const options::RunOptions d = options::defaults(registry::EngineKind::dsmc);
    const options::RunOptions e = options::defaults(registry::EngineKind::edmd);
    for (const options::Option& opt : options::run_table()) {
      py::list engines;
      py::dict defaults;
      for (const auto& [kind, r] : {std::pair{registry::EngineKind::dsmc, &d},
                                    std::pair{registry::EngineKind::edmd, &e}})
        if (options::applies(opt, kind)) {
          engines.append(std::string(registry::name(kind)));
          defaults[py::str(std::string(registry::name(kind)))] = python_value(*r, opt);
        }
      std::string help(opt.help);
      if (opt.details) help += " " + opt.details();
      py::dict row;
      row["name"] = options::cli_name(opt), row["python"] = options::python_name(opt);
      row["engines"] = engines, row["use"] = use_name(opt.use);
      row["type"] = std::string(options::type_name(opt)), row["default"] = defaults;
      row["unit"] = std::string(opt.unit), row["help"] = help;
      row["unset"] = std::string(opt.unset), row["initial_state"] = opt.initial_state;
      rows.append(row);
    }
    return rows;
  }, "The run options of the command's table: name, Python name, engines, use, type, "
     "default per engine, unit, help.");
  m.def("check_option", [](const std::string& engine, const std::string& name,
                           const py::handle& value) {
    const options::Option* opt = options::find(name);
    if (!opt) throw std::invalid_argument("no option " + name);
    options::RunOptions o = options::defaults(registry::engine(engine));
    set_value(o, *opt, value);
  }, "Checks one value against its option's type and range (ValueError/TypeError).");
  m.def("given_velocity_keywords",
        [] { return engine_keywords(registry::EngineKind::dsmc, true); });
  py::class_<Schedule>(m, "Schedule", "The sampling instants of a run (hypergas/schedule.hpp)")
      .def(py::init([](double t0, double until, double every) {
             return Schedule::make(t0, until, every);
           }),
           py::arg("t0"), py::arg("until"), py::arg("every") = 0.0)
      .def_property_readonly("rows", &Schedule::rows)
      .def_property_readonly("intervals", &Schedule::intervals)
      .def_property_readonly("every", &Schedule::every)
      .def("time", &Schedule::time, py::arg("k"));
}

}  // namespace hypergas::python
