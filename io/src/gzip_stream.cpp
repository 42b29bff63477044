#include "gzip_stream.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <new>
#include <stdexcept>
#include <vector>

#include <zlib.h>

#include "foldkit/io/file_name.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::io::detail {
namespace {

constexpr const char* kSuffix = ".gz";
// Compressed bytes read from the file, and written to it, at a time.
constexpr std::size_t kChunk = std::size_t(256) << 10;
// gzip's wrapper around deflate data (zlib's windowBits: 15, plus 16 for the gzip header).
constexpr int kGzipWindow = 15 + 16;
// Level 1 (gzip -1): CMML's repetitive markup shrinks 13 to 14 times, at the speed of writing
// the text; level 6 shrinks it only a little more for several times the time.
constexpr int kLevel = 1;

}  // namespace

bool gzip_name(const std::string& path) { return has_extension(path, kSuffix); }

std::string without_gzip_suffix(const std::string& path) {
  return gzip_name(path) ? path.substr(0, path.size() - std::strlen(kSuffix)) : path;
}

struct TextReader::State {
  std::string path;
  std::FILE* file = nullptr;
  std::size_t size = 0;
  bool gzip = false;
  z_stream z{};
  bool inflating = false;  // z holds an inflate state to end
  bool finished = false;   // the last gzip member ended and no input is left
  // Bytes read from the file and not yet used: z.next_in and z.avail_in say which, for a plain
  // file too (whose bytes are copied out as they are).
  std::vector<unsigned char> in = std::vector<unsigned char>(kChunk);
  std::size_t newlines = 0;  // in the text handed out so far, for the line of an error
  bool any = false;          // whether any text was handed out

  ~State() {
    if (inflating) inflateEnd(&z);
    if (file) std::fclose(file);
  }

  // The compressed input, refilled when zlib has used it up; false at the end of the file.
  bool refill() {
    if (z.avail_in > 0) return true;
    const std::size_t n = std::fread(in.data(), 1, in.size(), file);
    if (n == 0 && std::ferror(file)) fail(std::string("read error: ") + std::strerror(errno));
    z.next_in = in.data();
    z.avail_in = static_cast<uInt>(n);
    return n > 0;
  }

  [[noreturn]] void fail(const std::string& what) const { throw ParseError(path, any ? static_cast<int>(newlines) + 1 : 0, what); }

  // Inflates into [data, data + max); how many bytes it wrote (0 only once the text has ended).
  std::size_t inflate_into(char* data, std::size_t max) {
    z.next_out = reinterpret_cast<Bytef*>(data);
    z.avail_out = static_cast<uInt>(std::min<std::size_t>(max, UINT_MAX));
    const uInt room = z.avail_out;
    while (z.avail_out > 0 && !finished) {
      const bool more = refill();
      const uInt out_before = z.avail_out;
      const int rc = inflate(&z, Z_NO_FLUSH);
      if (rc == Z_STREAM_END) {
        // Another member may follow (gzip -d reads them as one text); anything else is corrupt.
        if (!refill()) finished = true;
        else if (inflateReset(&z) != Z_OK) throw std::bad_alloc();
      } else if (rc == Z_MEM_ERROR) {
        throw std::bad_alloc();
      } else if (rc == Z_DATA_ERROR || rc == Z_NEED_DICT || rc == Z_STREAM_ERROR) {
        count(data, room - z.avail_out);
        fail(std::string("corrupt gzip data (") + (z.msg ? z.msg : "invalid data") + ")");
      } else if (!more && z.avail_out == out_before) {
        // Z_BUF_ERROR or Z_OK with no input left and nothing produced: the stream stops early.
        count(data, room - z.avail_out);
        fail("truncated gzip data: the file ends before its compressed stream does");
      }
    }
    return room - z.avail_out;
  }

  void count(const char* data, std::size_t n) {
    newlines += static_cast<std::size_t>(std::count(data, data + n, '\n'));
    any = any || n > 0;
  }
};

TextReader::TextReader(const std::string& path) : s_(std::make_unique<State>()) {
  s_->path = path;
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw ParseError(path, 0, "is a directory, not a file");
  s_->file = std::fopen(path.c_str(), "rb");
  if (!s_->file) throw ParseError(path, 0, std::string("cannot open: ") + std::strerror(errno));
  const auto size = std::filesystem::file_size(path, ec);
  s_->size = ec ? 0 : static_cast<std::size_t>(size);
  // The first bytes decide: kept in the input buffer, they are the start of either text.
  s_->refill();
  s_->gzip = s_->z.avail_in >= 2 && s_->in[0] == 0x1f && s_->in[1] == 0x8b;
  if (s_->gzip) {
    if (inflateInit2(&s_->z, kGzipWindow) != Z_OK) throw std::bad_alloc();
    s_->inflating = true;
  }
}

TextReader::~TextReader() = default;

bool TextReader::compressed() const { return s_->gzip; }

std::size_t TextReader::file_size() const { return s_->size; }

bool TextReader::read(std::string& out, std::size_t max) {
  const std::size_t old = out.size();
  out.resize(old + max);
  std::size_t n = 0;
  if (s_->gzip) {
    n = s_->inflate_into(&out[old], max);
  } else {
    while (n < max && s_->refill()) {
      const std::size_t take = std::min<std::size_t>(max - n, s_->z.avail_in);
      std::memcpy(&out[old + n], s_->z.next_in, take);
      s_->z.next_in += take;
      s_->z.avail_in -= static_cast<uInt>(take);
      n += take;
    }
  }
  out.resize(old + n);
  s_->count(out.data() + old, n);
  return n > 0;
}

struct GzipWriter::State {
  Sink out;
  z_stream z{};
  bool deflating = false;
  std::vector<unsigned char> buffer = std::vector<unsigned char>(kChunk);

  ~State() {
    if (deflating) deflateEnd(&z);
  }

  // Runs deflate over the pending input with `flush`, handing every full buffer to the sink.
  void run(int flush) {
    for (;;) {
      z.next_out = buffer.data();
      z.avail_out = static_cast<uInt>(buffer.size());
      const int rc = deflate(&z, flush);
      if (rc == Z_STREAM_ERROR) throw std::logic_error("gzip: deflate state corrupt");
      const std::size_t n = buffer.size() - z.avail_out;
      if (n > 0) out(reinterpret_cast<const char*>(buffer.data()), n);
      if (flush == Z_FINISH ? rc == Z_STREAM_END : (z.avail_in == 0 && z.avail_out > 0)) return;
    }
  }
};

GzipWriter::GzipWriter(Sink out) : s_(std::make_unique<State>()) {
  s_->out = std::move(out);
  if (deflateInit2(&s_->z, kLevel, Z_DEFLATED, kGzipWindow, 8, Z_DEFAULT_STRATEGY) != Z_OK) throw std::bad_alloc();
  s_->deflating = true;
}

GzipWriter::~GzipWriter() = default;

void GzipWriter::write(std::string_view text) {
  while (!text.empty()) {
    const std::size_t take = std::min<std::size_t>(text.size(), UINT_MAX);
    s_->z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
    s_->z.avail_in = static_cast<uInt>(take);
    s_->run(Z_NO_FLUSH);
    text.remove_prefix(take);
  }
}

void GzipWriter::finish() {
  s_->z.next_in = nullptr;
  s_->z.avail_in = 0;
  s_->run(Z_FINISH);
}

}  // namespace foldkit::io::detail
