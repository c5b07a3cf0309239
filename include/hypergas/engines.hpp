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
