// The "did you mean" rule (hypergas/options/suggest.hpp): edit distances by hand, and which
// misspellings get a suggestion.
#include <catch2/catch.hpp>

#include "hypergas/options/suggest.hpp"

using namespace hypergas::options;

TEST_CASE("edit distance: insertions, deletions, substitutions and swaps count 1", "[options]") {
  CHECK(edit_distance("", "") == 0);
  CHECK(edit_distance("abc", "") == 3);
  CHECK(edit_distance("packing", "packing") == 0);
  CHECK(edit_distance("packnig", "packing") == 1);      // one swap of neighbours
  CHECK(edit_distance("restitutoin", "restitution") == 1);
  CHECK(edit_distance("pakcing", "packing") == 1);
  CHECK(edit_distance("seeds", "seed") == 1);            // one insertion
  CHECK(edit_distance("kitten", "sitting") == 3);        // the textbook pair
  CHECK(edit_distance("ca", "abc") == 3);                // optimal string alignment, not 2
}

TEST_CASE("nearest: a near name is suggested, a far one is not", "[options]") {
  const std::vector<std::string> names{"--restitution", "--packing", "--n", "--dim", "--seed"};
  CHECK(nearest("--restitutoin", names) == "--restitution");
  CHECK(nearest("--packnig", names) == "--packing");
  CHECK(nearest("--dmi", names) == "--dim");
  CHECK(nearest("--zzzzzz", names).empty());
  CHECK(nearest("--temperature", names).empty());
  CHECK(did_you_mean("--seeed", names) == "; did you mean '--seed'?");
  CHECK(did_you_mean("runn", {"run", "bench"}) == "; did you mean 'run'?");
  CHECK(did_you_mean("x", {}).empty());
}
