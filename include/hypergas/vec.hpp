// hypergas/vec.hpp -- the one spelling of a D-dimensional vector and the list of dimensions.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <string>
#include <type_traits>
#include <utility>

#include "hypergas/error.hpp"

namespace hypergas {

/// Smallest and largest supported dimension. Every templated module is instantiated for
/// exactly these (see `for_each_dim`), and the CLI dispatcher maps the runtime value here.
inline constexpr int min_dim = 1;
inline constexpr int max_dim = 6;

/// A dimension the library supports.
template <int D>
concept Dimension = (D >= min_dim && D <= max_dim);

/// A D-dimensional column vector of doubles (velocity in units of the run, or position).
template <int D>
using Vec = Eigen::Matrix<double, D, 1>;

/// Tag type carrying a dimension, for type lists (`TEMPLATE_TEST_CASE`, dispatch).
template <int D>
using DimTag = std::integral_constant<int, D>;

/// Calls `f(DimTag<D>{})` for D = 1..6 in order.
template <class F>
constexpr void for_each_dim(F&& f) {
  [&]<int... Ds>(std::integer_sequence<int, Ds...>) {
    (f(DimTag<Ds + 1>{}), ...);
  }
  (std::make_integer_sequence<int, max_dim>{});
}

/// Throws InvalidInput for a dimension outside min_dim..max_dim (for_dim and
/// registry::dimension check with it).
inline void check_dimension(int d) {
  if (d < min_dim || d > max_dim)
    throw InvalidInput("dimension must be in " + std::to_string(min_dim) + ".." +
                       std::to_string(max_dim) + ", got " + std::to_string(d));
}

/// Calls `f(DimTag<D>{})` for the runtime dimension d (D = d) and returns what f returns
/// (the same type for every D), through a table of function pointers: the one place where a
/// runtime dimension becomes a template argument. Throws InvalidInput for d outside
/// min_dim..max_dim.
template <class F>
decltype(auto) for_dim(int d, F&& f) {
  check_dimension(d);
  using R = decltype(f(DimTag<min_dim>{}));
  using Fn = R (*)(F&);
  static constexpr auto table = []<int... Ds>(std::integer_sequence<int, Ds...>) {
    return std::array<Fn, sizeof...(Ds)>{
        [](F& g) -> R { return g(DimTag<Ds + min_dim>{}); }...};
  }(std::make_integer_sequence<int, max_dim - min_dim + 1>{});
  return table[static_cast<std::size_t>(d - min_dim)](f);
}

}  // namespace hypergas
