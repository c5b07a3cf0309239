// Atomic file output: mkstemp in the destination folder, write, fsync, rename.
#include "hypergas/analysis/output.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>

#include "hypergas/error.hpp"

namespace hypergas::analysis {

namespace {
std::string errno_text(int e) {
  return std::strerror(e);
}

// Writes all of `text` to fd; false on an error (errno set).
bool write_all(int fd, const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t w = ::write(fd, p, left);
    if (w < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    p += w;
    left -= static_cast<std::size_t>(w);
  }
  return true;
}

void put_double(std::ostream& os, double x) {
  if (std::isnan(x)) {
    os << "nan";
  } else if (std::isinf(x)) {
    os << (x > 0 ? "inf" : "-inf");
  } else {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.17g", x);
    os << buf;
  }
}

void put_json_string(std::ostream& os, const std::string& s) {
  os << '"';
  for (unsigned char ch : s) {
    switch (ch) {
      case '"':
        os << "\\\"";
        break;
      case '\\':
        os << "\\\\";
        break;
      case '\n':
        os << "\\n";
        break;
      case '\t':
        os << "\\t";
        break;
      case '\r':
        os << "\\r";
        break;
      default:
        if (ch < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", ch);
          os << buf;
        } else {
          os << static_cast<char>(ch);
        }
    }
  }
  os << '"';
}
}  // namespace

void write_file_atomic(const std::string& path, const std::function<void(std::ostream&)>& write) {
  namespace fs = std::filesystem;
  const fs::path target(path);
  if (target.filename().empty()) throw InvalidInput("cannot write '" + path + "': not a file name");
  const fs::path folder = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw InvalidInput("cannot write '" + path + "': folder '" + folder.string() +
                       "' does not exist or is not a folder");
  // Produce the whole text first: a throwing writer leaves nothing on disk.
  std::ostringstream text;
  write(text);
  if (!text) throw InvalidInput("cannot write '" + path + "': formatting failed");

  // Hidden temporary next to the target (same file system, so rename is atomic).
  std::string tmp_name(1, '.');
  tmp_name += target.filename().string();
  tmp_name += ".tmp.XXXXXX";
  std::string tmp = (folder / tmp_name).string();
  const int fd = ::mkstemp(tmp.data());
  if (fd < 0)
    throw InvalidInput("cannot write '" + path + "': cannot create a file in folder '" +
                       folder.string() + "' (" + errno_text(errno) + ")");
  const std::string data = text.str();
  bool ok = write_all(fd, data) && ::fchmod(fd, 0644) == 0 && ::fsync(fd) == 0;
  int err = ok ? 0 : errno;
  if (::close(fd) != 0 && ok) {
    ok = false;
    err = errno;
  }
  if (ok && std::rename(tmp.c_str(), path.c_str()) != 0) {
    ok = false;
    err = errno;
  }
  if (!ok) {
    ::unlink(tmp.c_str());
    throw InvalidInput("cannot write '" + path + "': " + errno_text(err));
  }
}

void write_csv(const std::string& path, const std::vector<std::string>& columns,
               const std::vector<std::vector<double>>& rows) {
  if (columns.empty()) throw InvalidInput("write_csv '" + path + "': no columns");
  for (std::size_t r = 0; r < rows.size(); ++r)
    if (rows[r].size() != columns.size())
      throw InvalidInput("write_csv '" + path + "': row " + std::to_string(r) + " has " +
                         std::to_string(rows[r].size()) + " values for " +
                         std::to_string(columns.size()) + " columns");
  write_file_atomic(path, [&](std::ostream& os) {
    for (std::size_t c = 0; c < columns.size(); ++c) os << (c ? "," : "") << columns[c];
    os << '\n';
    for (const auto& row : rows) {
      for (std::size_t c = 0; c < row.size(); ++c) {
        if (c) os << ',';
        if (std::isfinite(row[c])) put_double(os, row[c]);  // empty: undefined (see header)
      }
      os << '\n';
    }
  });
}

std::string to_json(const JsonObject& fields) {
  std::ostringstream os;
  os << '{';
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) os << ", ";
    put_json_string(os, fields[i].first);
    os << ": ";
    std::visit(
        [&os](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, bool>) {
            os << (v ? "true" : "false");
          } else if constexpr (std::is_integral_v<T>) {  // int64, and uint64 (seeds)
            os << v;
          } else if constexpr (std::is_same_v<T, double>) {
            if (std::isfinite(v))
              put_double(os, v);
            else
              os << "null";
          } else {
            put_json_string(os, v);
          }
        },
        fields[i].second);
  }
  os << '}';
  return os.str();
}

void write_json(const std::string& path, const JsonObject& fields) {
  const std::string text = to_json(fields);
  write_file_atomic(path, [&](std::ostream& os) { os << text << '\n'; });
}

}  // namespace hypergas::analysis
