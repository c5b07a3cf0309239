// h5md/src/isolated_reader.cpp -- h5md::read_state: the frame is read in a child process
// (read_state_here, reader.cpp) and sent back through a pipe, in the encoding below.
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "reader.hpp"

namespace hypergas::h5md {

using namespace detail;

namespace {

// The reading runs in a child process: the HDF5 library reads past its buffers on some
// damaged files (heap overflows inside H5Dread, found by tests/unit/test_h5md.cpp's byte
// flips), and what a damaged file does to the library must not become a crash, nor
// memory corruption, of the command. The child sends the state (or the error's one line)
// through a pipe and exits; a child that dies says the file is damaged.

void put(std::string& out, const void* p, std::size_t n) {
  if (n == 0) return;  // an empty vector's data() may be null
  out.append(static_cast<const char*>(p), n);
}
template <class T>
void put_vector(std::string& out, const std::vector<T>& v) {
  const std::uint64_t n = v.size();
  put(out, &n, sizeof n);
  put(out, v.data(), n * sizeof(T));
}

struct Cursor {
  const std::string& in;
  std::size_t at = 0;
  void get(void* p, std::size_t n) {
    if (at + n > in.size()) throw std::out_of_range("short message");
    if (n == 0) return;  // an empty vector's data() may be null: no memcpy from or to it
    std::memcpy(p, in.data() + at, n);
    at += n;
  }
  template <class T>
  void get_vector(std::vector<T>& v) {
    std::uint64_t n = 0;
    get(&n, sizeof n);
    if (n > (in.size() - at) / sizeof(T)) throw std::out_of_range("short message");
    v.resize(n);
    get(v.data(), n * sizeof(T));
  }
};

std::string encode(const State& s) {
  std::string out(1, 'S');
  put(out, &s.dim, sizeof s.dim);
  const std::uint64_t n = s.n;
  put(out, &n, sizeof n);
  put(out, &s.frames, sizeof s.frames);
  put(out, &s.frame, sizeof s.frame);
  put(out, &s.step, sizeof s.step);
  put(out, &s.time, sizeof s.time);
  put(out, &s.box, sizeof s.box);
  put_vector(out, s.velocities);
  put_vector(out, s.positions);
  put_vector(out, s.species);
  put_vector(out, s.mass);
  return out;
}

State decode(const std::string& in) {
  State s;
  Cursor c{in, 1};
  std::uint64_t n = 0;
  c.get(&s.dim, sizeof s.dim);
  c.get(&n, sizeof n);
  s.n = static_cast<std::size_t>(n);
  c.get(&s.frames, sizeof s.frames);
  c.get(&s.frame, sizeof s.frame);
  c.get(&s.step, sizeof s.step);
  c.get(&s.time, sizeof s.time);
  c.get(&s.box, sizeof s.box);
  c.get_vector(s.velocities);
  c.get_vector(s.positions);
  c.get_vector(s.species);
  c.get_vector(s.mass);
  if (c.at != in.size()) throw std::out_of_range("long message");
  return s;
}

bool write_all(int fd, const std::string& m) {
  std::size_t done = 0;
  while (done < m.size()) {
    const ssize_t k = ::write(fd, m.data() + done, m.size() - done);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) return false;
    done += std::size_t(k);
  }
  return true;
}


}  // namespace

State read_state(const std::string& path, std::int64_t frame) {
  int fds[2];
  if (::pipe(fds) != 0) return read_state_here(path, frame);  // no pipe: read here
  std::fflush(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]), ::close(fds[1]);
    return read_state_here(path, frame);
  }
  if (pid == 0) {  // the child: read, send, leave without running the parent's exit code
    ::close(fds[0]);
    std::string m;
    try {
      m = encode(read_state_here(path, frame));
    } catch (const std::exception& e) {
      m = std::string("E") + e.what();
    }
    ::_exit(write_all(fds[1], m) ? 0 : 1);
  }
  ::close(fds[1]);
  std::string m;
  char buf[1 << 16];
  for (;;) {
    const ssize_t k = ::read(fds[0], buf, sizeof buf);
    if (k < 0 && errno == EINTR) continue;
    if (k <= 0) break;
    m.append(buf, std::size_t(k));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const bool clean = WIFEXITED(status) && WEXITSTATUS(status) == 0;
  if (clean && !m.empty() && m[0] == 'E') fail(m.substr(1));
  if (clean && !m.empty() && m[0] == 'S') {
    try {
      return decode(m);
    } catch (const std::out_of_range&) {
    }
  }
  fail(path + ": a damaged HDF5 file (reading it failed inside the HDF5 library)");
}

}  // namespace hypergas::h5md
