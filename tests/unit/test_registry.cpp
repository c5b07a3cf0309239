// The registry: every name round-trips, unknown names are rejected with the known ones
// listed, and the one dispatch reaches exactly the chosen (D, model, species) instantiation
// for every combination; both engines satisfy the engine concept.
#include <catch2/catch.hpp>

#include <string>
#include <type_traits>

#include "hypergas/dsmc/engine.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/engine_concept.hpp"
#include "hypergas/registry.hpp"

using namespace hypergas;

static_assert(SimulationEngine<dsmc::Engine<1, dsmc::HardSpheres>>);
static_assert(
    SimulationEngine<dsmc::Engine<6, dsmc::VariableHardSpheres, Features{.species = true}>>);
static_assert(SimulationEngine<edmd::Engine<2>>);
static_assert(SimulationEngine<edmd::Engine<5, Features{.positions = true, .species = true},
                                            edmd::SlabScan>>);

TEST_CASE("registry: dispatch reaches the chosen types for every combination", "[registry]") {
  const auto names = registry::model_names();
  REQUIRE(names.size() == registry::Models::size);
  for (int d = min_dim; d <= max_dim; ++d)
    for (std::size_t m = 0; m < names.size(); ++m)
      for (bool two : {false, true}) {
        const std::string got = registry::dispatch(
            [](auto dim, auto model, auto species) {
              using Model = typename decltype(model)::type;
              static_assert(dsmc::CollisionModel<Model>);
              std::string id = std::to_string(decltype(dim)::type::value);
              id.append(Model::name).append(decltype(species)::type::value ? "+species" : "");
              return id;
            },
            registry::dimension(d), registry::model(names[m]), registry::species(two));
        std::string want = std::to_string(d);
        want.append(names[m]).append(two ? "+species" : "");
        REQUIRE(got == want);
      }
  int seen = 0;  // a void-returning dispatch, one axis
  registry::dispatch([&](auto dim) { seen = decltype(dim)::type::value; }, registry::dimension(4));
  REQUIRE(seen == 4);
}

TEST_CASE("registry: unknown names and dimensions are rejected with the known ones",
          "[registry]") {
  REQUIRE_THROWS_AS(registry::dimension(0), InvalidInput);
  REQUIRE_THROWS_AS(registry::dimension(max_dim + 1), InvalidInput);
  REQUIRE_THROWS_WITH(registry::model("soft"), Catch::Contains("hs, maxwell, vhs"));
  REQUIRE_THROWS_WITH(registry::engine("md"), Catch::Contains("dsmc, edmd"));
  REQUIRE_THROWS_WITH(registry::initial_state("hot"), Catch::Contains("two-temp"));
  REQUIRE_THROWS_AS(registry::scheme("euler"), InvalidInput);
}

TEST_CASE("registry: every entry's name round-trips and has a help text", "[registry]") {
  for (const auto& e : registry::initial_states) {
    REQUIRE(registry::initial_state(e.name) == e.value);
    REQUIRE(registry::name(e.value) == e.name);
    REQUIRE(!e.help.empty());
  }
  for (const auto& e : registry::engines) REQUIRE(registry::engine(e.name) == e.value);
  for (const auto& e : registry::schemes) REQUIRE(registry::scheme(e.name) == e.value);
  for (auto n : registry::model_names()) REQUIRE(registry::describe_models().find(n) != std::string::npos);
  REQUIRE(registry::name(registry::default_initial_state(registry::EngineKind::dsmc)) == "delta");
  REQUIRE(registry::name(registry::default_initial_state(registry::EngineKind::edmd)) == "maxwell");
}

TEST_CASE("registry: model traits come from the model types", "[registry]") {
  const registry::ModelTraits hs = registry::model_traits("hs", 0.3);
  REQUIRE(hs.exponent == dsmc::HardSpheres::exponent());
  REQUIRE(!hs.isotropic_scattering);
  REQUIRE(hs.supports_drive);
  const registry::ModelTraits mm = registry::model_traits("maxwell", 0.3);
  REQUIRE(mm.exponent == 0.0);
  REQUIRE(mm.isotropic_scattering);
  REQUIRE(!mm.supports_drive);
  const registry::ModelTraits vhs = registry::model_traits("vhs", 0.3);
  REQUIRE(vhs.exponent == 0.3);  // a run parameter
  REQUIRE(vhs.isotropic_scattering);
  REQUIRE(!vhs.supports_drive);
  REQUIRE_THROWS_AS(registry::model_traits("soft", 0.3), InvalidInput);
}

TEST_CASE("registry: EDMD scan names resolve to the policy types", "[registry]") {
  REQUIRE(registry::scan_names().front() == "auto");
  for (auto n : registry::scan_names()) {
    const std::string got = registry::dispatch(
        [](auto dim, auto scan) {
          using Scan = registry::ScanFor<typename decltype(scan)::type, decltype(dim)::type::value>;
          return std::string(Scan::name);
        },
        registry::dimension(6), registry::scan(n));
    REQUIRE(got == (n == "auto" ? std::string("filtered") : std::string(n)));
  }
  REQUIRE_THROWS_WITH(registry::scan("heap"), Catch::Contains("slab, horizon, filtered"));
}
