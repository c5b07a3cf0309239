// hypergas/checkpoint.hpp -- binary checkpoint files: a writer and a reader that share one
// description of each class's state.
//
// A class that can be saved and restored lists its state once:
//
//   template <class Archive> void io(Archive& a) { a.tag("queue"); a(t_, next_, cur_, base_); }
//
// The same function saves (Archive = checkpoint::Writer) and restores (checkpoint::Reader).
// `a(x...)` takes trivially copyable values (numbers, enums, std::array, plain structs), the
// std::vector and std::basic_string of such values, vectors of those (one level), and any
// class with its own `io`. `a.tag(name)` writes a section name and on reading checks it, so
// that a file from another layout is refused at the first difference, not read as garbage.
// `Archive::saving` tells the two apart where they must differ (e.g. an engine that rebuilds
// a derived array after loading).
//
// File layout (all integers little-endian; docs/checkpoints.md):
//   magic "HGCKPT\r\n" (8 bytes) | format version u32 | 0x01020304 u32 | payload bytes u64
//   payload: a sequence of records; a vector or string is its element count (u64) followed
//            by its raw bytes, a value is its raw bytes, a tag is a string
//   trailer: checksum u64 of magic..payload | "HGCKEND\n" (8 bytes)
// The checksum is a 64-bit multiply-xorshift hash over 8-byte words (the last word padded
// with zeros): changing any one word of the file always changes it, and other corruption
// passes with probability about 2^-64. The reader checks size, magic, version, byte order and
// checksum before it parses anything, and every element count against the bytes left, so a
// truncated, corrupted or foreign file is refused with InvalidInput and never read.
//
// The writer streams to `<path>.tmp`, fsyncs it and renames it over `path` (commit()), so
// `path` always holds the previous complete checkpoint or the new one, never a partial file.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "hypergas/error.hpp"

#include <fcntl.h>
#include <unistd.h>

namespace hypergas::checkpoint {

/// Version of the file layout and of every class's io() list; a reader refuses other versions
/// (naming both). Raised by one on every change of the layout or of any io() list, however
/// small (docs/checkpoints.md keeps the history).
inline constexpr std::uint32_t format_version = 9;

namespace detail {

/// Running 64-bit hash over 8-byte words (see the file comment).
class WordHash {
 public:
  void add(const unsigned char* p, std::size_t n);
  /// The hash of everything added, the last partial word padded with zeros.
  std::uint64_t finish() const;

 private:
  void word(std::uint64_t w);
  std::uint64_t h_ = 0x6a09e667f3bcc909ULL;
  unsigned char pend_[8]{};
  std::size_t npend_ = 0;
  std::uint64_t total_ = 0;
};

template <class T>
struct is_vector : std::false_type {};
template <class T, class A>
struct is_vector<std::vector<T, A>> : std::true_type {};
template <class T>
struct is_string : std::false_type {};
template <class C, class Tr, class A>
struct is_string<std::basic_string<C, Tr, A>> : std::true_type {};

template <class T, class Ar>
concept HasIo = requires(T& t, Ar& a) { t.io(a); };

}  // namespace detail

/// Streams a checkpoint to `<path>.tmp`; commit() makes it `path`. Without commit() (an
/// exception, or destruction), the temporary file is removed and `path` is untouched.
class Writer {
 public:
  static constexpr bool saving = true;
  /// Opens `<path>.tmp`; throws std::runtime_error if it cannot be created.
  explicit Writer(std::string path);
  ~Writer();
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  void bytes(const void* p, std::size_t n);
  void tag(std::string_view name) { str(name); }

  template <class... T>
  void operator()(const T&... xs) {
    (one(xs), ...);
  }

  /// Writes the trailer, flushes, fsyncs, closes and renames over the final path (and fsyncs
  /// the folder). Throws std::runtime_error on any I/O failure (the old file then stays).
  void commit();
  /// Bytes written so far (header and payload).
  std::uint64_t size() const { return written_; }

 private:
  void str(std::string_view s) {
    const std::uint64_t n = s.size();
    bytes(&n, sizeof n);
    bytes(s.data(), s.size());
  }
  template <class T>
  void one(const T& x) {
    if constexpr (detail::HasIo<T, Writer>) {
      const_cast<T&>(x).io(*this);  // io() only reads when saving
    } else if constexpr (detail::is_string<T>::value) {
      static_assert(std::is_trivially_copyable_v<typename T::value_type>);
      const std::uint64_t n = x.size();
      bytes(&n, sizeof n);
      bytes(x.data(), n * sizeof(typename T::value_type));
    } else if constexpr (detail::is_vector<T>::value) {
      using E = typename T::value_type;
      const std::uint64_t n = x.size();
      bytes(&n, sizeof n);
      if constexpr (std::is_trivially_copyable_v<E> && !detail::HasIo<E, Writer>)
        bytes(x.data(), n * sizeof(E));
      else
        for (const E& e : x) one(e);
    } else {
      static_assert(std::is_trivially_copyable_v<T>, "checkpoint: add an io() to this type");
      bytes(&x, sizeof x);
    }
  }

  std::string path_, tmp_;
  std::FILE* f_ = nullptr;
  detail::WordHash hash_;
  std::uint64_t written_ = 0;
  long payload_pos_ = 0;
  bool done_ = false;
};

/// Reads a checkpoint written by Writer. The constructor checks the whole file (size, magic,
/// version, byte order, checksum) and throws InvalidInput naming the file and the problem.
class Reader {
 public:
  static constexpr bool saving = false;
  explicit Reader(std::string path);
  ~Reader();
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  void bytes(void* p, std::size_t n);
  /// Reads a section name; throws InvalidInput unless it is `name`.
  void tag(std::string_view name);

  template <class... T>
  void operator()(T&... xs) {
    (one(xs), ...);
  }

  /// Throws InvalidInput unless the whole payload was read (a layout mismatch).
  void finish();
  const std::string& path() const { return path_; }
  /// Throws InvalidInput "checkpoint '<path>': <what>".
  [[noreturn]] void fail(const std::string& what) const;

 private:
  std::uint64_t count(std::size_t element_size) {
    std::uint64_t n = 0;
    bytes(&n, sizeof n);
    if (element_size > 0 && n > left_ / element_size) fail("an array is longer than the file");
    return n;
  }
  template <class T>
  void one(T& x) {
    if constexpr (detail::HasIo<T, Reader>) {
      x.io(*this);
    } else if constexpr (detail::is_string<T>::value) {
      using E = typename T::value_type;
      x.resize(count(sizeof(E)));
      bytes(x.data(), x.size() * sizeof(E));
    } else if constexpr (detail::is_vector<T>::value) {
      using E = typename T::value_type;
      if constexpr (std::is_trivially_copyable_v<E> && !detail::HasIo<E, Reader>) {
        x.resize(count(sizeof(E)));
        bytes(x.data(), x.size() * sizeof(E));
      } else {
        x.resize(count(1));
        for (E& e : x) one(e);
      }
    } else {
      static_assert(std::is_trivially_copyable_v<T>, "checkpoint: add an io() to this type");
      bytes(&x, sizeof x);
    }
  }

  std::string path_;
  std::FILE* f_ = nullptr;
  std::uint64_t left_ = 0;  // payload bytes not yet read
};


// ---- implementation ---------------------------------------------------------------------

namespace detail {

inline constexpr char magic[8] = {'H', 'G', 'C', 'K', 'P', 'T', '\r', '\n'};
inline constexpr char end_mark[8] = {'H', 'G', 'C', 'K', 'E', 'N', 'D', '\n'};
inline constexpr std::uint32_t order_mark = 0x01020304u;
inline constexpr std::size_t header_bytes = 8 + 4 + 4 + 8;
inline constexpr std::size_t trailer_bytes = 8 + 8;

inline void WordHash::word(std::uint64_t w) {
  h_ ^= w;
  h_ *= 0x9e3779b97f4a7c15ULL;  // odd: a bijection of h for fixed w, as are the xor-shifts
  h_ ^= h_ >> 29;
  h_ *= 0xbf58476d1ce4e5b9ULL;
  h_ ^= h_ >> 32;
}

inline void WordHash::add(const unsigned char* p, std::size_t n) {
  total_ += n;
  if (npend_ > 0 && npend_ < 8) {  // complete the pending word first
    const std::size_t take = std::min(n, 8 - npend_);
    std::memcpy(pend_ + npend_, p, take);
    npend_ += take, p += take, n -= take;
    if (npend_ < 8) return;
    std::uint64_t w;
    std::memcpy(&w, pend_, 8);
    word(w);
    npend_ = 0;
  }
  for (; n >= 8; p += 8, n -= 8) {
    std::uint64_t w;
    std::memcpy(&w, p, 8);
    word(w);
  }
  if (n > 0 && n < 8) {  // npend_ is 0 here
    std::memcpy(pend_, p, n);
    npend_ = n;
  }
}

inline std::uint64_t WordHash::finish() const {
  WordHash c = *this;
  if (c.npend_ > 0) {
    std::uint64_t w = 0;
    std::memcpy(&w, c.pend_, c.npend_);
    c.word(w);
  }
  c.word(total_);
  return c.h_;
}

}  // namespace detail

inline Writer::Writer(std::string path) : path_(std::move(path)), tmp_(path_ + ".tmp") {
  static_assert(std::endian::native == std::endian::little,
                "checkpoint files are little-endian; add byte swapping for this platform");
  f_ = std::fopen(tmp_.c_str(), "wb");
  if (!f_)
    throw std::runtime_error("cannot create checkpoint '" + tmp_ + "': " + std::strerror(errno));
  unsigned char head[detail::header_bytes] = {};  // the size field is filled in by commit()
  std::memcpy(head, detail::magic, 8);
  std::memcpy(head + 8, &format_version, 4);
  std::memcpy(head + 12, &detail::order_mark, 4);
  hash_.add(head, 16);  // the size field is hashed after the payload (commit())
  payload_pos_ = 16;
  if (std::fwrite(head, 1, sizeof head, f_) != sizeof head)
    throw std::runtime_error("cannot write checkpoint '" + tmp_ + "': " + std::strerror(errno));
  written_ = sizeof head;
}

inline Writer::~Writer() {
  if (f_) std::fclose(f_);
  if (!done_) std::remove(tmp_.c_str());
}

inline void Writer::bytes(const void* p, std::size_t n) {
  if (n == 0) return;
  hash_.add(static_cast<const unsigned char*>(p), n);
  if (std::fwrite(p, 1, n, f_) != n)
    throw std::runtime_error("cannot write checkpoint '" + tmp_ + "': " + std::strerror(errno));
  written_ += n;
}

inline void Writer::commit() {
  const std::uint64_t payload = written_ - detail::header_bytes;
  hash_.add(reinterpret_cast<const unsigned char*>(&payload), 8);
  const std::uint64_t sum = hash_.finish();
  const auto fail = [&](const char* what) {
    throw std::runtime_error("cannot " + std::string(what) + " checkpoint '" + tmp_ +
                             "': " + std::strerror(errno));
  };
  if (std::fwrite(&sum, 1, 8, f_) != 8 || std::fwrite(detail::end_mark, 1, 8, f_) != 8)
    fail("write");
  if (std::fseek(f_, payload_pos_, SEEK_SET) != 0 || std::fwrite(&payload, 1, 8, f_) != 8)
    fail("write");
  if (std::fflush(f_) != 0 || ::fsync(::fileno(f_)) != 0) fail("flush");
  const int rc = std::fclose(f_);
  f_ = nullptr;
  if (rc != 0) fail("close");
  if (std::rename(tmp_.c_str(), path_.c_str()) != 0) fail("rename");
  done_ = true;
  // Make the rename itself durable.
  std::string dir = path_;
  const auto slash = dir.find_last_of('/');
  dir = slash == std::string::npos ? "." : dir.substr(0, slash + 1);
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd >= 0) {
    ::fsync(fd);
    ::close(fd);
  }
}

inline Reader::Reader(std::string path) : path_(std::move(path)) {
  f_ = std::fopen(path_.c_str(), "rb");
  if (!f_) fail(std::string("cannot open: ") + std::strerror(errno));
  if (std::fseek(f_, 0, SEEK_END) != 0) fail("cannot seek");
  const long size = std::ftell(f_);
  std::rewind(f_);
  if (size < static_cast<long>(detail::header_bytes + detail::trailer_bytes))
    fail("truncated or not a hypergas checkpoint (too short)");
  unsigned char head[detail::header_bytes];
  if (std::fread(head, 1, sizeof head, f_) != sizeof head) fail("cannot read the header");
  if (std::memcmp(head, detail::magic, 8) != 0) fail("not a hypergas checkpoint (bad magic)");
  std::uint32_t version = 0, order = 0;
  std::uint64_t payload = 0;
  std::memcpy(&version, head + 8, 4);
  std::memcpy(&order, head + 12, 4);
  std::memcpy(&payload, head + 16, 8);
  if (order != detail::order_mark) fail("written on a machine of other byte order");
  if (version != format_version)
    fail("checkpoint format " + std::to_string(version) + ", this build reads format " +
         std::to_string(format_version) +
         "; continue the run with the build that wrote it, or start it again");
  if (payload != static_cast<std::uint64_t>(size) - detail::header_bytes - detail::trailer_bytes)
    fail("truncated or extended: its size does not match its header");
  // Checksum pass over the header (without the size field) and the payload.
  detail::WordHash h;
  h.add(head, 16);
  std::vector<unsigned char> buf(1 << 20);
  for (std::uint64_t left = payload; left > 0;) {
    const std::size_t k = static_cast<std::size_t>(std::min<std::uint64_t>(left, buf.size()));
    if (std::fread(buf.data(), 1, k, f_) != k) fail("cannot read the payload");
    h.add(buf.data(), k);
    left -= k;
  }
  h.add(head + 16, 8);
  unsigned char tail[detail::trailer_bytes];
  if (std::fread(tail, 1, sizeof tail, f_) != sizeof tail) fail("cannot read the trailer");
  std::uint64_t sum = 0;
  std::memcpy(&sum, tail, 8);
  if (std::memcmp(tail + 8, detail::end_mark, 8) != 0) fail("truncated (no end mark)");
  if (sum != h.finish()) fail("corrupted (checksum mismatch)");
  if (std::fseek(f_, static_cast<long>(detail::header_bytes), SEEK_SET) != 0) fail("cannot seek");
  left_ = payload;
}

inline Reader::~Reader() {
  if (f_) std::fclose(f_);
}

inline void Reader::fail(const std::string& what) const {
  throw InvalidInput("checkpoint '" + path_ + "': " + what);
}

inline void Reader::bytes(void* p, std::size_t n) {
  if (n > left_) fail("ends early: it does not match this version's layout");
  if (n > 0 && std::fread(p, 1, n, f_) != n) fail("read error");
  left_ -= n;
}

inline void Reader::tag(std::string_view name) {
  std::string s;
  one(s);
  if (s != name)
    fail("expected section '" + std::string(name) + "', found '" + s.substr(0, 40) +
         "': written by another build or for another run");
}

inline void Reader::finish() {
  if (left_ != 0) fail("has unread data: it does not match this version's layout");
}

}  // namespace hypergas::checkpoint
