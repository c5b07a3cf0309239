// options/src/suggest.cpp -- the nearest name by edit distance (suggest.hpp).
#include "hypergas/options/suggest.hpp"

#include <algorithm>
#include <cstddef>

namespace hypergas::options {

int edit_distance(std::string_view a, std::string_view b) {
  const std::size_t n = a.size(), m = b.size();
  // d[i][j]: distance between the first i characters of a and the first j of b
  std::vector<std::vector<int>> d(n + 1, std::vector<int>(m + 1, 0));
  for (std::size_t i = 0; i <= n; ++i) d[i][0] = static_cast<int>(i);
  for (std::size_t j = 0; j <= m; ++j) d[0][j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= n; ++i)
    for (std::size_t j = 1; j <= m; ++j) {
      const int cost = a[i - 1] == b[j - 1] ? 0 : 1;
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[n][m];
}

std::string nearest(std::string_view name, const std::vector<std::string>& candidates) {
  const int limit = name.size() <= 4 ? 1 : name.size() <= 8 ? 2 : 3;
  std::string best;
  int best_d = limit + 1;
  for (const std::string& c : candidates) {
    const int dist = edit_distance(name, c);
    if (dist < best_d) best_d = dist, best = c;
  }
  return best;
}

std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates,
                         std::string_view quote) {
  const std::string n = nearest(name, candidates);
  if (n.empty()) return {};
  return "; did you mean " + std::string(quote) + n + std::string(quote) + "?";
}

}  // namespace hypergas::options
