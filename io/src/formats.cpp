#include "foldkit/io/formats.hpp"

#include <cmath>

#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/io/cmml.hpp"
#include "foldkit/io/drawn_lines.hpp"
#include "foldkit/io/file_name.hpp"
#include "foldkit/io/fold_format.hpp"
#include "foldkit/io/pmml.hpp"
#include "foldkit/io/svg.hpp"
#include "gzip_stream.hpp"

namespace foldkit::io {

namespace {

// Speed of the one event a pattern's state becomes in CMML (30 °/s, the CLI's since its start).
constexpr double kCmmlSpeed = 30.0 * M_PI / 180.0;

std::vector<FileFormat> make_formats() {
  std::vector<FileFormat> all;
  all.push_back({FileKind::Pmml, "PMML", ".pmml", "application/xml",
                 [](const std::string& path, const geometry::BuildOptions& options) {
                   return PatternFile{read_pmml(path, options), std::nullopt, {}};
                 },
                 [](const geometry::CreasePattern& p, const PatternOutput&) { return write_pmml(p); }, false});
  all.push_back({FileKind::Cmml, "CMML", ".cmml", "application/xml", nullptr,
                 [](const geometry::CreasePattern& p, const PatternOutput& out) {
                   if (!out.state) throw std::invalid_argument("a .cmml output needs fold angles, and this input has none");
                   return write_cmml(geometry::sequence_to(p, *out.state, kCmmlSpeed, p.title()));
                 },
                 true});
  all.push_back({FileKind::Fold, "FOLD", ".fold", "application/json",
                 [](const std::string& path, const geometry::BuildOptions& options) {
                   FoldImport f = read_fold(path, options);
                   return PatternFile{std::move(f.pattern), std::move(f.state), std::move(f.warnings)};
                 },
                 [](const geometry::CreasePattern& p, const PatternOutput& out) {
                   FoldExport extra;
                   if (out.state) extra.state = *out.state;
                   return write_fold(p, extra);
                 },
                 false});
  all.push_back({FileKind::Svg, "SVG", ".svg", "image/svg+xml", read_svg_pattern,
                 [](const geometry::CreasePattern& p, const PatternOutput& out) {
                   SvgOptions svg;
                   svg.joint_ids = out.joint_ids;
                   svg.state = out.state;
                   return write_svg(p, svg);
                 },
                 false});
  all.push_back({FileKind::Cp, "ORIPA .cp", ".cp", "text/plain; charset=utf-8", read_cp_pattern, nullptr, false});
  all.push_back({FileKind::Opx, "ORIPA .opx", ".opx", "application/xml", read_opx_pattern, nullptr, false});
  return all;
}

}  // namespace

const std::vector<FileFormat>& file_formats() {
  static const std::vector<FileFormat> all = make_formats();
  return all;
}

// A compressed file is its format's (X.cmml.gz is CMML): the suffix is stripped here, once, for
// every caller; writing compresses by it (AtomicFile), reading by the file's first bytes.
const FileFormat* format_of(const std::string& path) {
  const std::string name = detail::without_gzip_suffix(path);
  for (const FileFormat& f : file_formats())
    if (has_extension(name, f.extension)) return &f;
  return nullptr;
}

std::string extensions(const std::function<bool(const FileFormat&)>& which) {
  std::vector<const std::string*> listed;
  for (const FileFormat& f : file_formats())
    if (which(f)) listed.push_back(&f.extension);
  std::string text;
  for (std::size_t i = 0; i < listed.size(); ++i) {
    if (i > 0) text += i + 1 == listed.size() ? " or " : ", ";
    text += *listed[i];
  }
  return text;
}

PatternFile read_pattern_file(const std::string& path, const geometry::BuildOptions& options) {
  const FileFormat* f = format_of(path);
  if (!f || !f->read_pattern)
    throw UnknownFormat(path + ": a crease pattern must be a " + extensions(reads_patterns) + " file");
  return f->read_pattern(path, options);
}

std::string pattern_text(const std::string& path, const geometry::CreasePattern& pattern, const PatternOutput& output) {
  const FileFormat* f = format_of(path);
  if (!f || !f->write_pattern) throw UnknownFormat(path + ": unknown output type (use " + extensions(writes_patterns) + ")");
  try {
    return f->write_pattern(pattern, output);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(path + ": " + e.what());
  }
}

}  // namespace foldkit::io
