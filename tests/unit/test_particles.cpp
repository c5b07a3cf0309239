// Compile-time proof that absent particle fields cost nothing (include/hypergas/particles.hpp).
#include <catch2/catch.hpp>

#include <cstdint>
#include <type_traits>
#include <vector>

#include "hypergas/particles.hpp"

using namespace hypergas;

namespace {
constexpr Features velocity_only{};
constexpr Features with_positions{.positions = true};
constexpr Features everything{.positions = true, .species = true};

template <int D, Features F>
concept HasPosition = requires(Particles<D, F> p) {
  p.position(0);
};
template <int D, Features F>
concept HasSpeciesMass = requires(Particles<D, F> p) {
  p.set_species_mass(0, 1.0);
};
template <int D, Features F>
concept Storable = requires { typename Particles<D, F>; };
template <int D, Features F>
concept HasSpecies = requires(Particles<D, F> p) {
  p.species(0);
};
}  // namespace

// A velocity-space, single-mass scene stores one size and one vector: nothing else.
using Plain3 = Particles<3, velocity_only>;
static_assert(std::is_empty_v<Plain3::SpeciesArray>);
static_assert(std::is_empty_v<Plain3::SpeciesTable>);
static_assert(sizeof(Plain3) == sizeof(std::size_t) + sizeof(Plain3::FlatArray));
static_assert(sizeof(Particles<6, velocity_only>) == sizeof(Plain3));
// Positions share the state array: one [position, clock, velocity] record per particle,
// 8 doubles in 3D against 4 for velocities alone; each other field adds its container.
static_assert(sizeof(Particles<3, with_positions>) == sizeof(Plain3));
static_assert(Particles<3, with_positions>::stride == 8 && Plain3::stride == 4);
static_assert(Particles<6, with_positions>::stride == 16 && Particles<1, with_positions>::stride == 4);
static_assert(!std::is_empty_v<Particles<3, everything>::SpeciesArray>);
// Absent fields have no accessors: code that would use them does not compile.
static_assert(!HasPosition<3, velocity_only>);
static_assert(HasPosition<3, with_positions>);
static_assert(!HasSpeciesMass<3, velocity_only>);
static_assert(HasSpeciesMass<3, everything>);
static_assert(!HasSpecies<2, with_positions>);
static_assert(Storable<3, everything>);
static_assert(Plain3::stride == 4 && Particles<6>::stride == 8 && Particles<1>::stride == 1);

TEST_CASE("equal-mass 3D velocity storage uses 32 bytes per particle", "[particles]") {
  Plain3 p(1000);
  REQUIRE(p.bytes_per_particle() == 32.0);
  REQUIRE(p.inv_mass(17) == 1.0);
  Particles<3, with_positions> q(1000);
  REQUIRE(q.bytes_per_particle() == 64.0);
}

// A power-of-two record stays in one cache line only if the array starts on one; with
// Eigen's 16-byte allocator it starts 16 bytes past a line (glibc's large-block header),
// so every other 3D DSMC record straddles two lines. Sizes cover glibc's small
// (brk) and large (mmap) blocks; permute() reallocates.
TEST_CASE("the state array starts on a 64-byte cache line", "[particles]") {
  auto line_offset = [](const double* a) { return reinterpret_cast<std::uintptr_t>(a) % 64; };
  for (std::size_t n : {1ul, 3ul, 1000ul, 100000ul, 1000000ul}) {
    Plain3 p(n);
    CHECK(line_offset(p.velocity_data().data()) == 0);
    Particles<6, with_positions> q(n);
    CHECK(line_offset(q.velocity_data().data()) == 0);
  }
  Plain3 p(1000);
  std::vector<std::uint32_t> from(1000);
  for (std::uint32_t i = 0; i < 1000; ++i) from[i] = 999 - i;
  p.permute(from);
  CHECK(line_offset(p.velocity_data().data()) == 0);
}

TEST_CASE("fields read back what was written", "[particles]") {
  Particles<2, everything> p(3);
  p.velocity(1) = Vec<2>(1.0, -2.0);
  p.position(2) = Vec<2>(0.5, 0.25);
  p.set_species_mass(1, 4.0);
  p.set_species(2, 1);
  REQUIRE(p.velocity(1) == Vec<2>(1.0, -2.0));
  REQUIRE(p.velocity(0) == Vec<2>::Zero());
  REQUIRE(p.position(2) == Vec<2>(0.5, 0.25));
  REQUIRE(p.inv_mass(2) == 0.25);
  REQUIRE(p.species(2) == 1);
  p.set_species_mass(2, std::numeric_limits<double>::infinity());
  p.set_species(1, 2);
  REQUIRE(p.inv_mass(1) == 0.0);
  REQUIRE_THROWS_AS(p.set_species_mass(0, -1.0), InvalidInput);
  REQUIRE_THROWS_AS(p.set_species_mass(0, 0.0), InvalidInput);
  REQUIRE_THROWS_AS(p.set_species_mass(0, std::nan("")), InvalidInput);
  REQUIRE_THROWS_AS(p.set_species(0, max_species), InvalidInput);

  Particles<3, Features{.species = true}> s(4);
  s.set_species_mass(1, 10.0);
  s.set_species(3, 1);
  REQUIRE(s.inv_mass(3) == 0.1);
  REQUIRE(s.inv_mass(0) == 1.0);
}

TEST_CASE("position, clock and velocity share a record without aliasing; permute moves all",
          "[particles]") {
  Particles<3, Features{.positions = true, .species = true}> p(3);
  for (std::size_t i = 0; i < 3; ++i) {
    const double a = static_cast<double>(i);
    p.position(i) = Vec<3>(a, a + 0.1, a + 0.2);
    p.local_time(i) = 10.0 + a;
    p.velocity(i) = Vec<3>(-a, -a - 0.1, -a - 0.2);
    p.set_species(i, static_cast<int>(i));
  }
  for (std::size_t i = 0; i < 3; ++i) {
    const double a = static_cast<double>(i);
    REQUIRE(p.position(i) == Vec<3>(a, a + 0.1, a + 0.2));
    REQUIRE(p.local_time(i) == 10.0 + a);
    REQUIRE(p.velocity(i) == Vec<3>(-a, -a - 0.1, -a - 0.2));
  }
  p.permute({2, 0, 1});  // new i = old from[i]
  REQUIRE(p.position(0) == Vec<3>(2.0, 2.1, 2.2));
  REQUIRE(p.local_time(0) == 12.0);
  REQUIRE(p.velocity(1) == Vec<3>(-0.0, -0.1, -0.2));
  REQUIRE(p.species(2) == 1);
  REQUIRE_THROWS_AS(p.permute({0, 1}), InvalidInput);
}
