// hypergas/registry.hpp -- everything that can be instantiated, by name, and the one
// dispatch that turns runtime choices into template arguments.
//
// Compile-time choices are type lists: the dimensions 1..6, the DSMC collision models, the
// EDMD neighbour scans, the feature "two species". Runtime choices are tables of named
// entries: the engines, the DSMC time schemes and the initial states. Names, help texts and validation messages of the
// command, the studies, the benchmarks and the bindings all come from here.
//
//   registry::dispatch(
//       [&](auto dim, auto model, auto species) {
//         constexpr int D = decltype(dim)::type::value;        // DimTag<D>
//         using Model = typename decltype(model)::type;        // dsmc::HardSpheres, ...
//         constexpr bool two_species = decltype(species)::type::value;
//         ...
//       },
//       registry::dimension(3), registry::model("hs"), registry::species(false));
//
// Each axis is a `Choice` (an index into a type list); `dispatch` calls f once, with a
// std::type_identity tag per axis, through a table of function pointers per axis (no chain
// of comparisons). Every (D, model, species) combination a caller can reach is compiled, and
// only there.
//
// Adding a collision model: a model type with `name` and `help` (dsmc/models.hpp), its line
// in `Models` below, and its tests. Adding an initial state: its enumerator, its row in
// `initial_states` and its case in initial_state.hpp. Adding a dimension: raise max_dim in
// vec.hpp and the `Dims` list here (and the per-D geometry tables it needs).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "hypergas/dsmc/config.hpp"
#include "hypergas/dsmc/models.hpp"
#include "hypergas/edmd/config.hpp"
#include "hypergas/edmd/scan.hpp"
#include "hypergas/error.hpp"
#include "hypergas/initial_state.hpp"
#include "hypergas/vec.hpp"

namespace hypergas::registry {

/// A list of types: one axis of compile-time choices.
template <class... Ts>
struct TypeList {
  static constexpr std::size_t size = sizeof...(Ts);
};

/// The dimensions an engine is compiled for.
using Dims = TypeList<DimTag<1>, DimTag<2>, DimTag<3>, DimTag<4>, DimTag<5>, DimTag<6>>;
static_assert(Dims::size == max_dim - min_dim + 1, "Dims must list min_dim..max_dim");

/// The DSMC collision models (each has static `name` and `help`, dsmc/models.hpp).
using Models = TypeList<dsmc::HardSpheres, dsmc::MaxwellMolecules, dsmc::VariableHardSpheres>;

/// The EDMD neighbour-scan choice "auto": the measured fastest policy for the dimension
/// and density, edmd::AutoScan<D> or, from packing edmd::list_packing(D) on,
/// edmd::DenseScan<D> (`regime` and `RegimeScan` resolve it).
struct AutomaticScan {
  static constexpr std::string_view name = "auto";
  static constexpr std::string_view help =
      "the fastest scan for D and packing (slab, horizon, filtered, lists)";
};

/// The EDMD neighbour-scan policies (edmd/scan.hpp), "auto" first.
using Scans = TypeList<AutomaticScan, edmd::SlabScan, edmd::HorizonScan, edmd::FilteredScan,
                       edmd::ListScan>;

/// The density regimes of EDMD: below edmd::list_packing(D) (false) or from it on (true).
using Regimes = TypeList<std::false_type, std::true_type>;

/// The scan policy of the automatic choice in dimension D and regime Dense.
template <class Dense, int D>
using RegimeScan = std::conditional_t<Dense::value, edmd::DenseScan<D>, edmd::AutoScan<D>>;

/// The scan policy type of a Scans choice in dimension D, "auto" in regime Dense.
template <class Chosen, int D, class Dense = std::false_type>
using ScanFor = std::conditional_t<std::is_same_v<Chosen, AutomaticScan>,
                                   RegimeScan<Dense, D>, Chosen>;

/// The feature "two species" (Features::species): off, on.
using SpeciesFlags = TypeList<std::false_type, std::true_type>;

/// A runtime choice on the axis `List`: the index of the chosen type.
template <class List>
struct Choice {
  std::size_t index = 0;
};

/// A named entry of a runtime table, with its help text.
template <class Value>
struct Entry {
  Value value;
  std::string_view name;
  std::string_view help;
};

/// The engines.
enum class EngineKind { dsmc, edmd };
inline constexpr std::array<Entry<EngineKind>, 2> engines = {{
    {EngineKind::dsmc, "dsmc", "velocity-space collisions (the Kac/Boltzmann process)"},
    {EngineKind::edmd, "edmd", "event-driven hard-sphere MD in a periodic box"},
}};

/// The initial state an engine starts from when none is named, its Config's default: DSMC
/// relaxes from the delta shell, EDMD melts its lattice from Maxwell-Boltzmann velocities.
inline InitialState default_initial_state(EngineKind e) {
  return e == EngineKind::dsmc ? dsmc::Config{}.init : edmd::Config{}.init;
}

/// The initial velocity states (initial_state.hpp), for both engines.
inline constexpr std::array<Entry<InitialState>, 7> initial_states = {{
    {InitialState::maxwell, "maxwell", "Maxwell-Boltzmann at kT"},
    {InitialState::delta, "delta", "every speed equal, directions uniform"},
    {InitialState::cube, "cube", "velocities uniform in a cube"},
    {InitialState::beams, "beams", "two counter-streaming beams along x"},
    {InitialState::bimaxwell, "bimaxwell", "Gaussian with T_x / T_perp = 4"},
    {InitialState::bkw, "bkw", "the Bobylev-Krook-Wu state of Maxwell molecules"},
    {InitialState::two_temp, "two-temp", "two Maxwellian populations at different kT"},
}};

/// The DSMC time schemes.
inline constexpr std::array<Entry<dsmc::Scheme>, 3> schemes = {{
    {dsmc::Scheme::exact, "exact", "the exact Kac process (no time step)"},
    {dsmc::Scheme::ntc, "ntc", "Bird's no-time-counter scheme with a time step (--dt)"},
    {dsmc::Scheme::lanes, "lanes",
     "exact Kac processes of cache-sized lanes of particles, dealt anew every --epoch"},
}};

namespace detail {

template <class... Ts>
std::vector<std::string_view> type_names(TypeList<Ts...>) {
  return {Ts::name...};
}

template <class... Ts>
std::string describe_types(TypeList<Ts...>) {
  std::string s;
  ((s.append(s.empty() ? "" : " | ").append(Ts::name).append(" (").append(Ts::help).append(")")),
   ...);
  return s;
}

template <class Value, std::size_t K>
std::vector<std::string_view> entry_names(const std::array<Entry<Value>, K>& table) {
  std::vector<std::string_view> v;
  for (const auto& e : table) v.push_back(e.name);
  return v;
}

/// f(std::type_identity<T_k>{}) for the k-th type of the list, through a function table.
template <class F, class T0, class... Ts>
decltype(auto) visit(std::size_t k, F& f, TypeList<T0, Ts...>) {
  using R = decltype(f(std::type_identity<T0>{}));
  using Fn = R (*)(F&);
  static constexpr Fn table[] = {[](F& g) -> R { return g(std::type_identity<T0>{}); },
                                 [](F& g) -> R { return g(std::type_identity<Ts>{}); }...};
  return table[k](f);
}

}  // namespace detail

/// "a | b | c": the names of a table or type list joined by `sep`, for help texts.
inline std::string join(const std::vector<std::string_view>& names, std::string_view sep) {
  std::string s;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (k) s.append(sep);
    s.append(names[k]);
  }
  return s;
}

/// "name (help) | name (help) | ...": a table's entries for help texts.
template <class Value, std::size_t K>
std::string describe(const std::array<Entry<Value>, K>& table) {
  std::string s;
  for (const auto& e : table)
    s.append(s.empty() ? "" : " | ").append(e.name).append(" (").append(e.help).append(")");
  return s;
}
/// The collision models, as `describe` gives a table.
inline std::string describe_models() { return detail::describe_types(Models{}); }

/// Names in registry order.
inline std::vector<std::string_view> model_names() { return detail::type_names(Models{}); }
inline std::vector<std::string_view> scan_names() { return detail::type_names(Scans{}); }
inline std::vector<std::string_view> engine_names() { return detail::entry_names(engines); }
inline std::vector<std::string_view> initial_state_names() {
  return detail::entry_names(initial_states);
}
inline std::vector<std::string_view> scheme_names() { return detail::entry_names(schemes); }

/// The entry named `name` in `table`; throws InvalidInput naming `what` and the known names.
template <class Value, std::size_t K>
Value lookup(const std::array<Entry<Value>, K>& table, std::string_view name,
             std::string_view what) {
  for (const auto& e : table)
    if (e.name == name) return e.value;
  throw InvalidInput(std::string("unknown ") + std::string(what) + " '" + std::string(name) +
                     "' (known: " + join(detail::entry_names(table), ", ") + ")");
}

/// The name of `value` in `table` (every enumerator has a row).
template <class Value, std::size_t K>
std::string_view name_of(const std::array<Entry<Value>, K>& table, Value value) {
  for (const auto& e : table)
    if (e.value == value) return e.name;
  return "?";
}

inline EngineKind engine(std::string_view name) { return lookup(engines, name, "engine"); }
inline InitialState initial_state(std::string_view name) {
  return lookup(initial_states, name, "initial state");
}
inline dsmc::Scheme scheme(std::string_view name) { return lookup(schemes, name, "DSMC scheme"); }
inline std::string_view name(EngineKind e) { return name_of(engines, e); }
inline std::string_view name(InitialState s) { return name_of(initial_states, s); }
inline std::string_view name(dsmc::Scheme s) { return name_of(schemes, s); }

/// The dimension `d` as a choice; throws InvalidInput outside min_dim..max_dim.
inline Choice<Dims> dimension(int d) {
  check_dimension(d);
  return {static_cast<std::size_t>(d - min_dim)};
}

/// The type of `List` whose static `name` is `name`; throws InvalidInput naming `what` and
/// the known names.
template <class List>
Choice<List> choose(std::string_view name, std::string_view what) {
  const auto names = detail::type_names(List{});
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return {k};
  throw InvalidInput("unknown " + std::string(what) + " '" + std::string(name) +
                     "' (known: " + join(names, ", ") + ")");
}

/// The collision model named `name`; throws InvalidInput naming the known models.
inline Choice<Models> model(std::string_view name) {
  return choose<Models>(name, "model");
}

/// The EDMD neighbour scan named `name` ("auto" or a policy's name); throws InvalidInput.
inline Choice<Scans> scan(std::string_view name) { return choose<Scans>(name, "EDMD scan"); }

/// The density regime of an EDMD run in dimension dim at this packing fraction.
inline Choice<Regimes> regime(int dim, double packing) {
  return {packing >= edmd::list_packing(dim) ? 1u : 0u};
}

/// Two species (Features::species) or one.
inline Choice<SpeciesFlags> species(bool two) { return {two ? 1u : 0u}; }

/// The one dispatch: calls f(std::type_identity<T>{}...) with the chosen type of every axis,
/// in the order given, and returns what f returns (the same type for every choice, or void).
template <class F>
decltype(auto) dispatch(F&& f) {
  return f();
}
template <class F, class List, class... Lists>
decltype(auto) dispatch(F&& f, Choice<List> first, Choice<Lists>... rest) {
  auto bound = [&](auto tag) -> decltype(auto) {
    return dispatch([&](auto... tags) -> decltype(auto) { return f(tag, tags...); }, rest...);
  };
  return detail::visit(first.index, bound, List{});
}

/// An engine chosen at run time: the axes with_engine turns into one engine type.
struct EngineChoice {
  EngineKind engine = EngineKind::dsmc;
  int dim = 3;
  std::string_view model = dsmc::HardSpheres::name;  ///< DSMC collision model
  bool species = false;                               ///< two species (Features::species)
  std::string_view scan = AutomaticScan::name;        ///< EDMD neighbour scan
  double packing = 0.0;  ///< EDMD packing fraction: the regime of the automatic scan
};

/// What callers outside the engine need to know of a collision model (the model type's
/// static members, dsmc/models.hpp), as numbers: the exponent a of its pair rate |g|^a,
/// its scattering law and whether the white-noise drive applies to it.
struct ModelTraits {
  double exponent = 1.0;
  bool isotropic_scattering = false;
  bool supports_drive = false;
};

/// The traits of the model named `name`, with a = vhs_exponent for the model whose exponent
/// is a run parameter (vhs); throws InvalidInput for an unknown name.
inline ModelTraits model_traits(std::string_view name, double vhs_exponent) {
  return dispatch(
      [&](auto model) {
        using M = typename decltype(model)::type;
        double a = vhs_exponent;
        if constexpr (requires { M::exponent(); }) a = M::exponent();
        return ModelTraits{a, M::isotropic_scattering, M::supports_drive};
      },
      model(name));
}

}  // namespace hypergas::registry
