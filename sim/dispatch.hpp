// sim/dispatch.hpp -- the one place where runtime choices become template arguments.
//
// `dispatch_dim(d, f)` calls `f(DimTag<D>{})` with D == d for d in min_dim..max_dim (the list
// lives in hypergas/vec.hpp) and throws InvalidInput otherwise. `dispatch_model(m, f)` does
// the same for the DSMC collision model. Every instantiation of an engine for the command
// happens through these two functions, so the set of compiled (D, model) pairs is declared
// here and nowhere else.
#pragma once

#include <optional>
#include <string>
#include <type_traits>
#include <utility>

#include "hypergas/dsmc/models.hpp"
#include "hypergas/error.hpp"
#include "hypergas/vec.hpp"
#include "options.hpp"

namespace hypergas::cli {

namespace detail {
template <int First, class F, int... Ds>
auto dispatch_dim_impl(int d, F&& f, std::integer_sequence<int, Ds...>) {
  using R = decltype(f(DimTag<First>{}));
  if constexpr (std::is_void_v<R>) {
    const bool hit = ((d == First + Ds ? (f(DimTag<First + Ds>{}), true) : false) || ...);
    if (!hit) throw InvalidInput("dimension must be in 1..6, got " + std::to_string(d));
  } else {
    std::optional<R> r;
    ((d == First + Ds ? (r.emplace(f(DimTag<First + Ds>{})), true) : false) || ...);
    if (!r) throw InvalidInput("dimension must be in 1..6, got " + std::to_string(d));
    return std::move(*r);
  }
}
}  // namespace detail

/// Calls `f(DimTag<D>{})` for the runtime dimension `d` (1..6); returns what f returns
/// (the same type for every D, or void).
template <class F>
auto dispatch_dim(int d, F&& f) {
  return detail::dispatch_dim_impl<min_dim>(
      d, std::forward<F>(f), std::make_integer_sequence<int, max_dim - min_dim + 1>{});
}

/// Calls `f(std::type_identity<Model>{})` with the DSMC model type of `m` (HardSpheres,
/// MaxwellMolecules, VariableHardSpheres).
template <class F>
auto dispatch_model(dsmc::ModelKind m, F&& f) {
  switch (m) {
    case dsmc::ModelKind::hs: return f(std::type_identity<dsmc::HardSpheres>{});
    case dsmc::ModelKind::maxwell: return f(std::type_identity<dsmc::MaxwellMolecules>{});
    case dsmc::ModelKind::vhs: return f(std::type_identity<dsmc::VariableHardSpheres>{});
  }
  throw InvalidInput("unknown collision model");
}

/// Calls `f(std::bool_constant<b>{})`: turns a runtime choice (e.g. "two species") into a
/// compile-time feature flag.
template <class F>
auto dispatch_bool(bool b, F&& f) {
  if (b) return f(std::true_type{});
  return f(std::false_type{});
}

}  // namespace hypergas::cli
