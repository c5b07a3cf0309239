// hypergas/engines.hpp -- the one engine entry point: runtime choices (engine, dimension,
// collision model, species, EDMD scan) to one engine type.
//
//   registry::with_engine(choice, [&](auto engine) {
//     using Engine = typename decltype(engine)::type;   // dsmc::Engine<...> or edmd::Engine<...>
//     if constexpr (registry::is_dsmc<Engine>) ...
//   });
//
// The axes are the registry's type lists (registry.hpp); the dimension goes through
// for_dim (vec.hpp). A caller that compiles its engines per dimension (one translation unit
// per D, generated from an .inst.in file) calls with_engine<D> there.
#pragma once

#include <string_view>
#include <type_traits>

#include "hypergas/dsmc/engine.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/registry.hpp"

namespace hypergas::registry {

/// The DSMC engine type of (D, model, species).
template <int D, class Model, bool Species>
using DsmcEngine = dsmc::Engine<D, Model, Features{.species = Species}>;
/// The EDMD engine type of (D, species, scan policy).
template <int D, bool Species, class Scan>
using EdmdEngine = edmd::Engine<D, Features{.positions = true, .species = Species}, Scan>;

/// What an engine type was made of: `dsmc`, `features`, and `Model` (DSMC) or `Scan` (EDMD).
template <class E>
struct EngineTraits;
template <int D, class M, Features F>
struct EngineTraits<dsmc::Engine<D, M, F>> {
  static constexpr bool dsmc = true;
  static constexpr Features features = F;
  using Model = M;
};
template <int D, Features F, class S>
struct EngineTraits<edmd::Engine<D, F, S>> {
  static constexpr bool dsmc = false;
  static constexpr Features features = F;
  using Scan = S;
};

/// Whether E is a DSMC engine type (else EDMD).
template <class E>
inline constexpr bool is_dsmc = EngineTraits<E>::dsmc;

/// Every engine type that with_engine<D> reaches with the default scan list, as X(type), for
/// a literal D: compiled once per D by the engines library (engines/instances.cpp.in, which
/// checks this list against the registry's axes: detail::lists_every_engine) and declared extern
/// to every file that links it (engines/extern.hpp.in), so the command's runs, the studies
/// and the Python module share one compiled copy of each engine.
#define HYPERGAS_ENGINE_TYPES(D, X)                                                         \
  X(::hypergas::dsmc::Engine<D, ::hypergas::dsmc::HardSpheres, ::hypergas::Features{}>)     \
  X(::hypergas::dsmc::Engine<D, ::hypergas::dsmc::HardSpheres,                              \
                             ::hypergas::Features{.species = true}>)                        \
  X(::hypergas::dsmc::Engine<D, ::hypergas::dsmc::MaxwellMolecules, ::hypergas::Features{}>) \
  X(::hypergas::dsmc::Engine<D, ::hypergas::dsmc::MaxwellMolecules,                         \
                             ::hypergas::Features{.species = true}>)                        \
  X(::hypergas::dsmc::Engine<D, ::hypergas::dsmc::VariableHardSpheres,                      \
                             ::hypergas::Features{}>)                                       \
  X(::hypergas::dsmc::Engine<D, ::hypergas::dsmc::VariableHardSpheres,                      \
                             ::hypergas::Features{.species = true}>)                        \
  X(::hypergas::edmd::Engine<D, ::hypergas::Features{.positions = true},                    \
                             ::hypergas::edmd::AutoScan<D>>)                                \
  X(::hypergas::edmd::Engine<D, ::hypergas::Features{.positions = true, .species = true},   \
                             ::hypergas::edmd::AutoScan<D>>)                                \
  HYPERGAS_DENSE_ENGINES_##D(X)
/// The EDMD engines of the dense regime where DenseScan<D> is not AutoScan<D> (edmd/scan.hpp).
#define HYPERGAS_DENSE_ENGINES_1(X)
#define HYPERGAS_DENSE_ENGINES_2(X)
#define HYPERGAS_DENSE_ENGINES_3(X)                                                          \
  X(::hypergas::edmd::Engine<3, ::hypergas::Features{.positions = true},                    \
                             ::hypergas::edmd::DenseScan<3>>)                               \
  X(::hypergas::edmd::Engine<3, ::hypergas::Features{.positions = true, .species = true},   \
                             ::hypergas::edmd::DenseScan<3>>)
#define HYPERGAS_DENSE_ENGINES_4(X)
#define HYPERGAS_DENSE_ENGINES_5(X)
#define HYPERGAS_DENSE_ENGINES_6(X)

namespace detail {

template <class T, class... Ts>
constexpr bool listed(TypeList<Ts...>) {
  return (std::is_same_v<T, Ts> || ...);
}
template <int D, class Listed, class M, class... Ss>
constexpr bool dsmc_listed(TypeList<Ss...>) {
  return (listed<DsmcEngine<D, M, Ss::value>>(Listed{}) && ...);
}
template <int D, class Listed, class S, class... Rs>
constexpr bool edmd_listed(TypeList<Rs...>) {
  return (listed<EdmdEngine<D, S::value, RegimeScan<Rs, D>>>(Listed{}) && ...);
}
/// Whether `Listed` holds every engine that with_engine<D> reaches with the default scan
/// list (each model and species of DSMC; each species and density regime of EDMD).
template <int D, class Listed, class... Ms, class... Ss>
constexpr bool lists_every_engine(TypeList<Ms...>, TypeList<Ss...> species) {
  return (dsmc_listed<D, Listed, Ms>(species) && ...) &&
         (edmd_listed<D, Listed, Ss>(Regimes{}) && ...);
}

}  // namespace detail

/// The one engine entry point: calls f(std::type_identity<Engine>{}) with the engine type
/// that `c` names in dimension D (DSMC: model and species; EDMD: species and the scan, "auto"
/// resolved by the density regime) and returns what f returns (the same type for every
/// engine). The command, the studies and the Python module reach every engine through
/// here, so each engine type is compiled where a caller's f is, and only there. EDMD scans
/// other than "auto" are compiled only where a caller lists them (`ScanList`, a sublist of
/// `Scans`: the benchmarks). Throws InvalidInput for an unknown model or scan.
template <int D, class ScanList = TypeList<AutomaticScan>, class F>
decltype(auto) with_engine(const EngineChoice& c, F&& f) {
  if (c.engine == EngineKind::dsmc)
    return dispatch(
        [&](auto model, auto sp) -> decltype(auto) {
          return f(std::type_identity<DsmcEngine<D, typename decltype(model)::type,
                                                 decltype(sp)::type::value>>{});
        },
        model(c.model), species(c.species));
  const Choice<ScanList> chosen = choose<ScanList>(c.scan, "EDMD scan");
  // a named scan is the same in both regimes: only "auto" needs the density
  const bool automatic = c.scan == AutomaticScan::name;
  const Choice<Regimes> dense = automatic ? regime(D, c.packing) : Choice<Regimes>{};
  return dispatch(
      [&](auto sp, auto sc, auto rg) -> decltype(auto) {
        using Chosen = typename decltype(sc)::type;
        constexpr bool two = decltype(sp)::type::value;
        if constexpr (std::is_same_v<Chosen, AutomaticScan>)
          return f(std::type_identity<
                   EdmdEngine<D, two, RegimeScan<typename decltype(rg)::type, D>>>{});
        else
          return f(std::type_identity<EdmdEngine<D, two, Chosen>>{});
      },
      species(c.species), chosen, dense);
}

/// with_engine in the dimension c.dim (throws InvalidInput outside min_dim..max_dim).
template <class ScanList = TypeList<AutomaticScan>, class F>
decltype(auto) with_engine(const EngineChoice& c, F&& f) {
  return for_dim(c.dim, [&](auto dim) -> decltype(auto) {
    return with_engine<decltype(dim)::value, ScanList>(c, f);
  });
}

}  // namespace hypergas::registry

// The engines compiled once by the engines library, declared extern where it is linked.
#if __has_include("hypergas/engine_instances.hpp")
#include "hypergas/engine_instances.hpp"
#endif
