// hypergas/vec.hpp -- the one spelling of a D-dimensional vector and the list of dimensions.
#pragma once

#include <Eigen/Core>
#include <type_traits>

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

}  // namespace hypergas
