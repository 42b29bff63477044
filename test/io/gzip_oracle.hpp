#pragma once
// zlib used directly, as the oracle of the gzip tests: what foldkit writes must decompress, by
// zlib's own inflate and not by the code under test, to the plain file's bytes.
#include <stdexcept>
#include <string>

#include <zlib.h>

namespace foldkit::test {

// Inflates the gzip data `bytes` into `text`, member after member, until they end or zlib refuses
// them; zlib's last code: Z_STREAM_END when every byte decompressed.
inline int inflate_members(const std::string& bytes, std::string& text) {
  z_stream z{};
  if (inflateInit2(&z, 15 + 16) != Z_OK) throw std::runtime_error("inflateInit2");
  char out[1 << 16];
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(bytes.data()));
  z.avail_in = static_cast<uInt>(bytes.size());
  int rc = Z_OK;
  for (;;) {
    z.next_out = reinterpret_cast<Bytef*>(out);
    z.avail_out = sizeof out;
    rc = inflate(&z, Z_NO_FLUSH);
    text.append(out, sizeof out - z.avail_out);
    if (rc == Z_STREAM_END) {
      if (z.avail_in == 0) break;
      inflateReset(&z);
    } else if (rc != Z_OK) {
      break;
    }
  }
  inflateEnd(&z);
  return rc;
}

// The text of the gzip data `bytes` (every member, one after the other); throws when zlib refuses it.
inline std::string gunzip(const std::string& bytes) {
  std::string text;
  if (const int rc = inflate_members(bytes, text); rc != Z_STREAM_END)
    throw std::runtime_error("zlib refuses the data: " + std::to_string(rc));
  return text;
}

// What zlib can decompress of `bytes` before they end or go wrong: the text a reader of damaged
// data has seen when it stops.
inline std::string gunzip_prefix(const std::string& bytes) {
  std::string text;
  inflate_members(bytes, text);
  return text;
}

// `text` as one gzip member (zlib's default level).
inline std::string gzip(const std::string& text) {
  z_stream z{};
  if (deflateInit2(&z, Z_DEFAULT_COMPRESSION, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK) throw std::runtime_error("deflateInit2");
  std::string bytes(deflateBound(&z, static_cast<uLong>(text.size())) + 64, '\0');
  z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  z.avail_in = static_cast<uInt>(text.size());
  z.next_out = reinterpret_cast<Bytef*>(&bytes[0]);
  z.avail_out = static_cast<uInt>(bytes.size());
  const int rc = deflate(&z, Z_FINISH);
  bytes.resize(bytes.size() - z.avail_out);
  deflateEnd(&z);
  if (rc != Z_STREAM_END) throw std::runtime_error("deflate did not finish");
  return bytes;
}

}  // namespace foldkit::test
