// Pixel and voxel shape files: the ASCII-grid, PBM and voxel-layer readers.
#include "foldkit/io/shape_file.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>
#include <vector>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/file_name.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::io {
namespace {

using geometry::kMaxGridCells;
using geometry::PixelShape;
using geometry::VoxelShape;

std::string show(char c) {
  if (std::isprint(static_cast<unsigned char>(c)) != 0) return std::string("'") + c + "'";
  char buf[8];
  std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned>(static_cast<unsigned char>(c)));
  return buf;
}

struct Line {
  std::string text;
  int number = 0;
};

std::vector<Line> split_lines(const std::string& text) {
  std::vector<Line> lines;
  std::size_t pos = 0;
  int number = 1;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) end = text.size();
    std::string line = text.substr(pos, end - pos);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back({std::move(line), number++});
    pos = end + 1;
  }
  while (!lines.empty() && lines.back().text.empty()) lines.pop_back();
  return lines;
}

// Rows [begin, end) of `lines` as one grid layer appended to `cells`; returns its width.
int parse_rows(const std::vector<Line>& lines, std::size_t begin, std::size_t end, const std::string& file,
               std::vector<std::uint8_t>& cells) {
  const std::size_t width = lines[begin].text.size();
  for (std::size_t i = begin; i < end; ++i) {
    const Line& l = lines[i];
    if (l.text.empty()) throw ParseError(file, l.number, "blank line inside a grid");
    if (l.text.size() != width)
      throw ParseError(
          file, l.number,
          "ragged grid: this row has " + std::to_string(l.text.size()) + " columns, the first has " + std::to_string(width));
    if (cells.size() + width > kMaxGridCells)
      throw ParseError(file, l.number, "grid too large (more than " + std::to_string(kMaxGridCells) + " cells)");
    for (std::size_t x = 0; x < width; ++x) {
      const char c = l.text[x];
      if (c != '#' && c != '.' && c != ' ')
        throw ParseError(
            file, l.number,
            "unexpected character " + show(c) + " in column " + std::to_string(x + 1) + " (expected '#', '.' or ' ')");
      cells.push_back(c == '#' ? 1 : 0);
    }
  }
  return static_cast<int>(width);
}

bool any_filled(const std::vector<std::uint8_t>& cells) {
  return std::any_of(cells.begin(), cells.end(), [](std::uint8_t c) { return c != 0; });
}

// PBM header and P1 raster tokens, counting lines.
class PbmReader {
 public:
  PbmReader(const std::string& bytes, const std::string& file) : s_(bytes), file_(file) {}

  [[noreturn]] void fail(const std::string& message) const { throw ParseError(file_, line_, message); }

  void skip_space() {
    while (pos_ < s_.size()) {
      const char c = s_[pos_];
      if (c == '#') {
        while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c)) != 0) {
        if (c == '\n') ++line_;
        ++pos_;
      } else {
        return;
      }
    }
  }

  int number(const char* what) {
    skip_space();
    if (pos_ >= s_.size()) fail(std::string("missing ") + what);
    if (std::isdigit(static_cast<unsigned char>(s_[pos_])) == 0)
      fail(std::string("expected the ") + what + ", found " + show(s_[pos_]));
    long long v = 0;
    while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_])) != 0) {
      v = v * 10 + (s_[pos_++] - '0');
      if (v > static_cast<long long>(kMaxGridCells)) fail(std::string(what) + " too large");
    }
    if (v == 0) fail(std::string(what) + " is 0");
    return static_cast<int>(v);
  }

  std::size_t pos_ = 0;
  int line_ = 1;
  const std::string& s_;
  const std::string& file_;
};

}  // namespace

PixelShape parse_pixel_grid(const std::string& text, const std::string& file) {
  const std::vector<Line> lines = split_lines(text);
  if (lines.empty()) throw ParseError(file, 1, "empty grid");
  PixelShape shape;
  shape.width = parse_rows(lines, 0, lines.size(), file, shape.cells);
  shape.height = static_cast<int>(lines.size());
  if (!any_filled(shape.cells)) throw ParseError(file, lines.back().number, "the grid has no filled cell ('#')");
  return shape;
}

VoxelShape parse_voxel_layers(const std::string& text, const std::string& file) {
  if (text.rfind("VOX ", 0) == 0)
    throw ParseError(file, 1,
                     "a MagicaVoxel binary file; foldkit reads voxel text (layers of '#'/'.' grids, docs/HAMILTONIAN.md)");
  const std::vector<Line> lines = split_lines(text);
  VoxelShape shape;
  std::size_t i = 0;
  while (i < lines.size()) {
    if (lines[i].text.empty()) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < lines.size() && !lines[end].text.empty()) ++end;
    const int width = parse_rows(lines, i, end, file, shape.cells);
    const int height = static_cast<int>(end - i);
    if (shape.nz == 0) {
      shape.nx = width;
      shape.ny = height;
    } else if (width != shape.nx || height != shape.ny) {
      throw ParseError(file, lines[i].number,
                       "layer " + std::to_string(shape.nz + 1) + " is " + std::to_string(width) + "×" + std::to_string(height) +
                           ", the first is " + std::to_string(shape.nx) + "×" + std::to_string(shape.ny));
    }
    ++shape.nz;
    i = end;
  }
  if (shape.nz == 0) throw ParseError(file, 1, "empty voxel file");
  if (!any_filled(shape.cells)) throw ParseError(file, lines.back().number, "the voxel grid has no filled cell ('#')");
  return shape;
}

PixelShape parse_pbm(const std::string& bytes, const std::string& file) {
  PbmReader r(bytes, file);
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '1' && bytes[1] != '4'))
    r.fail("not a PBM file (expected the magic number P1 or P4)");
  const bool raw = bytes[1] == '4';
  r.pos_ = 2;
  PixelShape shape;
  shape.width = r.number("width");
  shape.height = r.number("height");
  const auto w = static_cast<std::size_t>(shape.width), h = static_cast<std::size_t>(shape.height);
  if (w * h > kMaxGridCells)
    r.fail("image of " + std::to_string(w) + "×" + std::to_string(h) + " pixels exceeds the limit of " +
           std::to_string(kMaxGridCells));
  shape.cells.assign(w * h, 0);
  const int header_line = r.line_;
  if (raw) {
    if (r.pos_ >= bytes.size() || std::isspace(static_cast<unsigned char>(bytes[r.pos_])) == 0)
      r.fail("expected one whitespace character before the raster");
    if (bytes[r.pos_] == '\n') ++r.line_;
    ++r.pos_;
    const std::size_t row_bytes = (w + 7) / 8, need = row_bytes * h, have = bytes.size() - r.pos_;
    if (have < need) r.fail("truncated raster: " + std::to_string(have) + " of " + std::to_string(need) + " bytes");
    if (have > need) r.fail("trailing data after the raster (" + std::to_string(have - need) + " bytes)");
    for (std::size_t y = 0; y < h; ++y)
      for (std::size_t x = 0; x < w; ++x)
        shape.cells[y * w + x] =
            static_cast<std::uint8_t>(static_cast<unsigned char>(bytes[r.pos_ + y * row_bytes + x / 8]) >> (7 - x % 8) & 1);
  } else {
    for (std::size_t k = 0; k < w * h; ++k) {
      r.skip_space();
      if (r.pos_ >= bytes.size()) r.fail("truncated raster: " + std::to_string(k) + " of " + std::to_string(w * h) + " pixels");
      const char c = bytes[r.pos_++];
      if (c != '0' && c != '1') r.fail("expected a pixel 0 or 1, found " + show(c));
      shape.cells[k] = c == '1' ? 1 : 0;
    }
    r.skip_space();
    if (r.pos_ < bytes.size()) r.fail("trailing data after the raster");
  }
  if (!any_filled(shape.cells)) throw ParseError(file, header_line, "the image has no filled pixel (1)");
  return shape;
}

bool is_voxel_path(const std::string& path) { return has_extension(path, ".vox"); }

PixelShape read_pixel_shape(const std::string& path) {
  const std::string bytes = read_file(path);
  const bool pbm = has_extension(path, ".pbm");
  return pbm ? parse_pbm(bytes, path) : parse_pixel_grid(bytes, path);
}

VoxelShape read_voxel_shape(const std::string& path) {
  return parse_voxel_layers(read_file(path), path);
}

}  // namespace foldkit::io
