// tests/unit/test_h5md.cpp -- the H5MD writer and reader (hypergas/h5md/h5md.hpp): a file
// written frame by frame reads back exactly, a resumed writer drops the frames after its
// checkpoint, and damaged files (every truncation length of a small file, random bytes
// overwritten) are refused with InvalidInput or read consistently, never crash.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include "hypergas/error.hpp"
#include "hypergas/h5md/h5md.hpp"

using namespace hypergas;
namespace fs = std::filesystem;

namespace {

struct TempFile {
  fs::path path;
  explicit TempFile(const std::string& name)
      : path(fs::temp_directory_path() / ("hypergas-test-" + std::to_string(::getpid()) + "-" + name)) {}
  ~TempFile() {
    std::error_code ec;
    fs::remove(path, ec);
  }
};

std::vector<double> frame_values(int frame, std::size_t n, int dim, double scale) {
  std::vector<double> v(n * std::size_t(dim));
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = scale * (double(frame) + 0.001 * double(k));
  return v;
}

h5md::Layout layout(int dim, std::size_t n, bool positions) {
  h5md::Layout l;
  l.dim = dim;
  l.n = n;
  l.positions = positions;
  l.observables = {"temperature"};
  l.creator_version = "test";
  return l;
}

void write_frames(h5md::Writer& w, int from, int to, std::size_t n, int dim, bool positions) {
  for (int f = from; f < to; ++f) {
    const auto v = frame_values(f, n, dim, 1.0);
    const auto x = frame_values(f, n, dim, 0.1);
    std::vector<std::int32_t> img(n * std::size_t(dim), f);
    const double obs = 1.0 + f;
    h5md::FrameData d;
    d.step = f;
    d.time = 0.5 * f;
    d.velocities = v.data();
    if (positions) d.positions = x.data(), d.images = img.data(), d.box = 10.0;
    d.observables = &obs;
    w.append(d);
  }
}

}  // namespace

TEST_CASE("h5md: frames written are read back exactly, in every dimension", "[h5md]") {
  for (int dim = 1; dim <= 6; ++dim)
    for (bool positions : {false, true}) {
      INFO("D = " << dim << ", positions " << positions);
      TempFile t("roundtrip.h5");
      const std::size_t n = 7;
      {
        h5md::Writer w(t.path.string(), layout(dim, n, positions));
        write_frames(w, 0, 4, n, dim, positions);
        REQUIRE(w.frames() == 4);
      }
      for (int k : {0, 2, 3, -1, -4}) {
        const h5md::State s = h5md::read_state(t.path.string(), k);
        const int f = k < 0 ? 4 + k : k;
        CHECK(s.dim == dim);
        CHECK(s.n == n);
        CHECK(s.frames == 4);
        CHECK(s.frame == std::uint64_t(f));
        CHECK(s.time == 0.5 * f);
        CHECK(s.step == f);
        CHECK(s.velocities == frame_values(f, n, dim, 1.0));
        CHECK(s.positions.empty() == !positions);
        if (positions) {
          CHECK(s.box == 10.0);
          CHECK(s.positions == frame_values(f, n, dim, 0.1));  // inside [0, 10): as written
        }
        CHECK(s.mass == std::vector<double>(n, 1.0));
      }
      CHECK_THROWS_AS(h5md::read_state(t.path.string(), 4), InvalidInput);
      CHECK_THROWS_AS(h5md::read_state(t.path.string(), -5), InvalidInput);
      const auto obs = h5md::read_observable(t.path.string(), "temperature");
      REQUIRE(obs.size() == 4);
      CHECK(obs[3].first == 1.5);
      CHECK(obs[3].second == 4.0);
    }
}

TEST_CASE("h5md: a resumed writer keeps the checkpoint's frames and appends after them",
          "[h5md]") {
  TempFile a("resume-a.h5"), b("resume-b.h5");
  const std::size_t n = 5;
  const int dim = 3;
  {
    h5md::Writer w(a.path.string(), layout(dim, n, true));
    write_frames(w, 0, 6, n, dim, true);  // frames 3..5 came after a checkpoint at 3
  }
  {
    h5md::Writer w = h5md::Writer::resume(a.path.string(), layout(dim, n, true), 3);
    CHECK(w.frames() == 3);
    write_frames(w, 3, 8, n, dim, true);
  }
  {
    h5md::Writer w(b.path.string(), layout(dim, n, true));
    write_frames(w, 0, 8, n, dim, true);
  }
  for (int k = 0; k < 8; ++k) {
    const auto x = h5md::read_state(a.path.string(), k), y = h5md::read_state(b.path.string(), k);
    CHECK(x.velocities == y.velocities);
    CHECK(x.positions == y.positions);
    CHECK(x.time == y.time);
  }
  CHECK(h5md::read_state(a.path.string()).frames == 8);
  CHECK_THROWS_AS(h5md::Writer::resume(a.path.string(), layout(dim, n, true), 9), InvalidInput);
}

TEST_CASE("h5md: damaged files are refused or read consistently, never a crash", "[h5md]") {
  TempFile good("fuzz-good.h5"), bad("fuzz-bad.h5");
  const std::size_t n = 6;
  const int dim = 2;
  {
    h5md::Writer w(good.path.string(), layout(dim, n, true));
    write_frames(w, 0, 3, n, dim, true);
  }
  std::ifstream in(good.path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  REQUIRE(bytes.size() > 1000);
  const auto check = [&](const std::string& content) {
    {
      std::ofstream out(bad.path, std::ios::binary | std::ios::trunc);
      out.write(content.data(), std::streamsize(content.size()));
    }
    try {
      const h5md::State s = h5md::read_state(bad.path.string(), -1);
      // read: what it returns must hold together
      CHECK(s.velocities.size() == s.n * std::size_t(s.dim));
      for (double v : s.velocities) CHECK(std::isfinite(v));
    } catch (const InvalidInput& e) {
      CHECK(std::string(e.what()).find('\n') == std::string::npos);  // one line
    }
  };
  // every truncation length up to the size, in steps (the short ones are all "not HDF5")
  for (std::size_t len = 0; len < bytes.size(); len += 97) check(bytes.substr(0, len));
  // random bytes overwritten: 200 files, 1 to 8 bytes each, seeded
  std::mt19937_64 rng(20261205);
  for (int trial = 0; trial < 200; ++trial) {
    std::string c = bytes;
    const int k = 1 + int(rng() % 8);
    for (int j = 0; j < k; ++j) c[rng() % c.size()] = char(rng() & 0xff);
    check(c);
  }
}
