#include "foldkit/io/atomic_write.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "atomic_file.hpp"
#include "foldkit/io/parse_error.hpp"
#include "gzip_stream.hpp"

namespace foldkit::io {
namespace fs = std::filesystem;

namespace detail {

AtomicFile::AtomicFile(const std::string& path) : path_(path) {
  // The name decides, as it decides the format (formats.cpp): X.cmml.gz is compressed CMML. Made
  // first, so that its failure leaves no temporary file behind.
  if (gzip_name(path)) gzip_ = std::make_unique<GzipWriter>([this](const char* data, std::size_t size) { write_bytes(data, size); });
  std::error_code ec;
  fs::path target(path);
  if (fs::is_symlink(target, ec)) {  // (a target that does not exist yet is no link: ec is ignored)
    target = fs::weakly_canonical(target, ec);
    if (ec) fail(ec.value());
  }
  target_ = target.string();
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  // A short fixed-length name, so that any name the target may have still fits.
  temp_ = (dir / ".foldkit-XXXXXX").string();
  fd_ = ::mkstemp(temp_.data());
  if (fd_ < 0) {
    const int err = errno;
    temp_.clear();  // no file was made: nothing to remove
    fail(err);
  }
  struct stat existing {};
  mode_t mode = 0;
  if (::stat(target_.c_str(), &existing) == 0) {
    mode = existing.st_mode & 07777;
  } else {
    const mode_t mask = ::umask(0);  // read the umask: a new file gets what open() would give it
    ::umask(mask);
    mode = 0666 & ~mask;
  }
  if (::fchmod(fd_, mode) != 0) fail(errno);
}

AtomicFile::~AtomicFile() {
  if (fd_ >= 0) ::close(fd_);
  if (!temp_.empty()) ::unlink(temp_.c_str());
}

void AtomicFile::fail(int err) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  if (!temp_.empty()) ::unlink(temp_.c_str());
  temp_.clear();
  throw WriteError(path_ + ": cannot write: " + std::strerror(err));
}

void AtomicFile::write_bytes(const char* data, std::size_t size) {
  if (fd_ < 0) throw WriteError(path_ + ": cannot write: the file was abandoned after an error");
  std::size_t done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd_, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) fail(n < 0 ? errno : EIO);
    done += static_cast<std::size_t>(n);
  }
}

void AtomicFile::write(std::string_view text) {
  if (gzip_) gzip_->write(text);
  else write_bytes(text.data(), text.size());
}

void AtomicFile::commit() {
  if (gzip_) gzip_->finish();
  if (fd_ < 0) throw WriteError(path_ + ": cannot write: the file was abandoned after an error");
  if (::fsync(fd_) != 0) fail(errno);
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail(errno);
  if (std::rename(temp_.c_str(), target_.c_str()) != 0) fail(errno);
  temp_.clear();
}

}  // namespace detail

void write_file_atomic(const std::string& path, const std::string& content) {
  detail::AtomicFile file(path);
  file.write(content);
  file.commit();
}

std::optional<std::string> read_file_if_present(const std::string& path) {
  std::error_code ec;
  const bool exists = std::filesystem::exists(path, ec);
  if (ec) throw ParseError(path, 0, "cannot be read: " + ec.message());
  if (!exists) return std::nullopt;
  return read_file(path);
}

std::string read_file(const std::string& path) {
  detail::TextReader in(path);
  std::string text;
  // A plain file's text is its size; a compressed one's grows as it is read.
  // (+ 1: the read that finds the end then needs no larger buffer).
  if (!in.compressed()) text.reserve(in.file_size() + 1);
  constexpr std::size_t kPiece = std::size_t(1) << 20;
  for (;;) {
    const std::size_t room = text.capacity() - text.size();
    if (!in.read(text, room > 0 ? room : kPiece)) return text;
  }
}

}  // namespace foldkit::io
