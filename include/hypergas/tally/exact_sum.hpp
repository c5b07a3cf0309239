// hypergas/tally/exact_sum.hpp -- an exact, order-independent sum of rounded terms.
//
// A term x (a double, in the sum's unit) is rounded once to an integer, round(x), and the
// integers are added exactly. The sum is therefore the same for every order of additions
// and removals: a sum kept up to date term by term (add the new value, remove the old one)
// equals, bit for bit, a sum of the current terms made from scratch, and sums kept by
// several threads add to the same result for every thread count.
//
// Storage: one 128-bit integer for |round(x)| < 2^96 (the terms of any physical state: the
// tally chooses its units so that a typical term is ~2^40, see tally.hpp), and, for larger
// terms, their mantissas summed per binary exponent in a sorted table (x >= 2^96 is an
// integer of 53 significant bits times 2^e; the table is empty in practice). The 128-bit
// part overflows only after 2^31 terms of 2^96 each.
//
// Terms below 2^51 take a branch-free path (to_units_fast); callers test the bound first
// (fast_limit).
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>
#include <map>
#include <utility>


namespace hypergas::tally {

__extension__ using int128 = __int128;

/// Terms with |x| below this are converted by to_units_fast.
inline constexpr double fast_limit = 0x1p51;

/// round(x) (to nearest, ties to even) for 0 <= x < 2^51: x + 1.5 2^52 has a fixed
/// exponent, so its low mantissa bits are round(x) + 2^51 (exact in the default rounding
/// mode). Plain double and integer arithmetic, so a loop over several terms vectorises.
[[gnu::always_inline]] inline std::int64_t to_units_fast(double x) {
  constexpr double magic = 0x1.8p52;
  return std::bit_cast<std::int64_t>(x + magic) - std::bit_cast<std::int64_t>(magic);
}

class ExactSum {
 public:
  /// Adds sign * round(x) for a finite term with |x| < fast_limit, as to_units_fast(x).
  void add_units(std::int64_t k) { low_ += k; }
  /// Adds sign * round(x) for any finite x (sign +1 or -1).
  void add(double x, int sign) {
    const double a = std::fabs(x);
    const int s = (x < 0.0) ? -sign : sign;
    if (a < fast_limit) {
      low_ += s * to_units_fast(a);
    } else if (a < 0x1p96) {
      low_ += s * static_cast<int128>(std::nearbyint(a));
    } else {
      int e = 0;
      const double m = std::frexp(a, &e);  // a = m 2^e, m in [0.5, 1)
      const auto mant = static_cast<std::int64_t>(std::ldexp(m, 53));  // exact
      int128& slot = high_[e - 53];
      slot += s * static_cast<int128>(mant);
      if (slot == 0) high_.erase(e - 53);
    }
  }
  /// Adds (sign = +1) or subtracts (-1) another sum.
  void merge(const ExactSum& o, int sign = 1) {
    low_ += sign * o.low_;
    for (const auto& [e, m] : o.high_) {
      int128& slot = high_[e];
      slot += sign * m;
      if (slot == 0) high_.erase(e);
    }
  }
  /// The sum as a double (the 128-bit part rounded once, then the table in exponent order):
  /// a function of the exact sum's representation only.
  double value() const {
    double v = static_cast<double>(low_);
    for (const auto& [e, m] : high_) v += std::ldexp(static_cast<double>(m), e);
    return v;
  }
  bool operator==(const ExactSum& o) const { return low_ == o.low_ && high_ == o.high_; }
  void clear() {
    low_ = 0;
    high_.clear();
  }


 private:
  int128 low_ = 0;
  std::map<int, int128> high_;  // exponent e -> sum of mantissas (each times 2^e)
};

}  // namespace hypergas::tally
