#include "foldkit/io/atomic_write.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "foldkit/io/parse_error.hpp"

namespace foldkit::io {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void fail(const std::string& path, int err) {
  throw WriteError(path + ": cannot write: " + std::strerror(err));
}

}  // namespace

void write_file_atomic(const std::string& path, const std::string& content) {
  std::error_code ec;
  fs::path target(path);
  if (fs::is_symlink(target, ec)) {  // (a target that does not exist yet is no link: ec is ignored)
    target = fs::weakly_canonical(target, ec);
    if (ec) fail(path, ec.value());
  }
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  // A short fixed-length name, so that any name the target may have still fits.
  std::string temp = (dir / ".foldkit-XXXXXX").string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) fail(path, errno);
  auto give_up = [&](int err) {
    ::close(fd);
    ::unlink(temp.c_str());
    fail(path, err);
  };
  struct stat existing {};
  mode_t mode = 0;
  if (::stat(target.c_str(), &existing) == 0) {
    mode = existing.st_mode & 07777;
  } else {
    const mode_t mask = ::umask(0);  // read the umask: a new file gets what open() would give it
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  if (::fchmod(fd, mode) != 0) give_up(errno);
  std::size_t done = 0;
  while (done < content.size()) {
    const ssize_t n = ::write(fd, content.data() + done, content.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) give_up(n < 0 ? errno : EIO);
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) give_up(errno);
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    fail(path, err);
  }
  if (std::rename(temp.c_str(), target.c_str()) != 0) {
    const int err = errno;
    ::unlink(temp.c_str());
    fail(path, err);
  }
}

std::string read_file(const std::string& path) {
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw ParseError(path, 0, "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream buf;
  buf << in.rdbuf();
  if (in.bad()) throw ParseError(path, 0, "read error");
  return buf.str();
}

}  // namespace foldkit::io
