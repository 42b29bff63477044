#include "foldkit/io/cmml.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string_view>

#include <tinyxml2.h>

#include "atomic_file.hpp"
#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/xml_reader.hpp"
#include "gzip_stream.hpp"
#include "text_lines.hpp"

namespace foldkit::io {
namespace {

using detail::has_name;
using tinyxml2::XMLElement;

std::pair<int, geometry::FoldCommand> read_fold(const detail::XmlInput& in, const XMLElement& e) {
  for (const XMLElement* c : in.children(e))
    if (!has_name(c, "EventNumber") && !has_name(c, "ID") && !has_name(c, "FoldAngle") && !has_name(c, "Velocity"))
      in.fail(*c, std::string("unknown element <") + c->Name() + "> in <Fold>");
  geometry::FoldCommand fold;
  fold.line = in.line(e);

  const XMLElement& ev = in.only_child(e, "EventNumber");
  const int event = in.integer(ev, "a non-negative integer");
  if (event < 0) in.fail(ev, "<EventNumber> must be a non-negative integer, found '" + in.leaf_text(ev) + "'");
  fold.joint_id = in.integer(in.only_child(e, "ID"), "an integer joint ID");

  const XMLElement& angle = in.only_child(e, "FoldAngle");
  const double degrees = in.number(angle);
  if (degrees < -180.0 || degrees > 180.0)
    in.fail(angle, "<FoldAngle> " + format_number(degrees) + " is outside [-180, 180] degrees");
  fold.angle = degrees_to_radians(degrees);

  const XMLElement& vel = in.only_child(e, "Velocity");
  const double speed = in.number(vel);
  if (!(speed > 0.0)) in.fail(vel, "<Velocity> must be positive (degrees per second), found " + format_number(speed));
  fold.speed = degrees_to_radians(speed);
  // A subnormal speed such as 5e-324 degrees/s is 0 rad/s once converted.
  if (!(fold.speed > 0.0))
    in.fail(vel, "<Velocity> must be positive (degrees per second), found " + format_number(speed) + " (too small)");
  return {event, fold};
}

[[noreturn]] void invalid(const geometry::FoldCommand& f, const std::string& what) {
  throw std::invalid_argument("write_cmml: joint " + std::to_string(f.joint_id) + " " + what);
}

// Degrees within [-180, 180], as read_cmml requires: angles within rounding of ±180° (and any
// beyond, which no sequence read from a file has) are written as ±180.
void append_angle(std::string& out, const geometry::FoldCommand& f) {
  if (!std::isfinite(f.angle)) invalid(f, "fold angle: not a finite number");
  char text[kDegreesChars];
  const double angle = std::clamp(f.angle, -M_PI, M_PI);
  const std::size_t size = format_degrees(angle, text);
  double degrees = 0.0;
  // Read back as every reader reads it (parse_numbers), where the text can reach ±180.
  if (std::abs(angle) > 3.14) std::from_chars(text, text + size, degrees);
  if (degrees > 180.0) out += "180";
  else if (degrees < -180.0) out += "-180";
  else out.append(text, size);
}

// The <Velocity> text: positive degrees per second that read back to a positive, finite speed.
void append_speed(std::string& out, const geometry::FoldCommand& f) {
  if (!std::isfinite(f.speed)) invalid(f, "speed: not a finite number");
  if (!(f.speed > 0.0)) invalid(f, "speed must be positive, found " + format_number(f.speed));
  if (!std::isfinite(f.speed * (180.0 / M_PI)))
    invalid(f, "speed " + format_number(f.speed) + " rad/s in degrees: not a finite number");
  char text[kDegreesChars];
  const std::size_t size = format_degrees(f.speed, text);
  if (f.speed > 1e-300) {  // its degrees are far from underflowing back to 0 rad/s
    out.append(text, size);
    return;
  }
  double degrees = 0.0;
  const auto [end, ec] = std::from_chars(text, text + size, degrees);
  if (ec != std::errc() || end != text + size || !(degrees_to_radians(degrees) > 0.0)) {
    const NumberList back = parse_numbers(std::string_view(text, size));  // its error names the text
    invalid(f, "speed " + format_number(f.speed) + " rad/s cannot be written: " + (back.error.empty() ? "too small" : back.error));
  }
  out.append(text, size);
}

// What the children of one <CMML> element add to a sequence being read.
struct CmmlReading {
  std::string title;
  bool titled = false;
  std::vector<std::pair<int, geometry::FoldCommand>> folds;

  void read(const detail::XmlInput& in, const XMLElement& root) {
    for (const XMLElement* c : in.children(root)) {
      if (has_name(c, "Title")) {
        if (titled) in.fail(*c, "<CMML> has more than one <Title>");
        titled = true;
        title = in.leaf_text(*c);
      } else if (has_name(c, "Fold")) {
        folds.push_back(read_fold(in, *c));
      } else {
        in.fail(*c, std::string("unknown element <") + c->Name() + "> in <CMML>");
      }
    }
  }
};

// Files from this size on are read a slice at a time (parse_cmml_sliced).
constexpr std::size_t kSlicedFrom = std::size_t(4) << 20;
constexpr std::size_t kSliceBytes = std::size_t(1) << 20;
// How much text a sliced reading takes from its source at a time.
constexpr std::size_t kPullBytes = std::size_t(256) << 10;

// Where a sliced reading's text comes from: appends the next piece to `buffer`; false, appending
// nothing, once the text is all read. A file's read errors (corrupt gzip data) are thrown as
// they come, at their line.
using Pull = std::function<bool(std::string& buffer)>;

// The text a sliced reading has pulled and not yet read: `text` from `start` on.
struct Pending {
  const Pull& pull;
  std::string text;
  std::size_t start = 0;

  std::string_view rest() const { return std::string_view(text).substr(start); }
  // Where `what` is in rest(), at or after `from`, pulling more as needed; npos when the text ends first.
  std::size_t find(std::string_view what, std::size_t from) {
    for (std::size_t searched = from;;) {
      const std::size_t at = rest().find(what, searched);
      if (at != std::string_view::npos) return at;
      // A match may begin in the last few bytes and end in the next piece.
      searched = std::max(from, rest().size() >= what.size() ? rest().size() - what.size() + 1 : 0);
      if (!more()) return std::string_view::npos;
    }
  }
  // Pulls one more piece, first dropping the text read when that is most of it (amortised: each
  // byte is moved about once however small the slices).
  bool more() {
    if (start > 0 && start >= text.size() / 2) {
      text.erase(0, start);
      start = 0;
    }
    return pull(text);
  }
  void consume(std::size_t n) { start += n; }
};

// Whether the text before <CMML> is what foldkit writes: a byte order mark, an XML declaration,
// white space.
bool plain_prefix(std::string_view prefix) {
  if (prefix.substr(0, 3) == "\xEF\xBB\xBF") prefix.remove_prefix(3);
  if (prefix.substr(0, 5) == "<?xml") {
    const std::size_t end = prefix.find("?>");
    if (end == std::string_view::npos) return false;
    prefix.remove_prefix(end + 2);
  }
  return detail::blank(prefix);
}

// Whether a piece of <CMML>'s body is free of what could hide "</Fold>" (a comment, CDATA, a
// processing instruction, a DOCTYPE) or nest another <CMML>.
bool plain_body(std::string_view body) {
  for (const char* what : {"<!", "<?", "<CMML", "</CMML"})
    if (body.find(what) != std::string_view::npos) return false;
  return true;
}

// The sliced reading of parse_cmml_sliced, from any source: the text is pulled as the slices
// need it, so that a file is never in memory whole.
std::optional<geometry::FoldSequence> read_sliced(const Pull& pull, const std::string& name, std::size_t slice_bytes) {
  // Only the plain shape foldkit writes: an optional declaration, <CMML>, then elements and text
  // with no comment, CDATA section, processing instruction or DOCTYPE (whose text could hold
  // "</Fold>"), and nothing after </CMML>. Anything else is read whole.
  Pending pending{pull, {}};
  const std::size_t open = pending.find("<CMML>", 0);
  if (open == std::string_view::npos || !plain_prefix(pending.rest().substr(0, open))) return std::nullopt;
  const std::string head(pending.rest().substr(0, open));
  pending.consume(open + 6);
  int line = detail::line_at(head, head.size());
  CmmlReading reading;
  for (bool first = true, last = false; !last; first = false) {
    // At least slice_bytes of <Fold> elements, up to the end of one; the rest when none ends later.
    const std::size_t fold_end = pending.find("</Fold>", std::max<std::size_t>(slice_bytes, 1));
    last = fold_end == std::string_view::npos;
    std::string_view body = pending.rest();
    if (last) {
      const std::size_t close = body.rfind("</CMML>");
      if (close == std::string_view::npos || !detail::blank(body.substr(close + 7))) return std::nullopt;
      body = body.substr(0, close);
    } else {
      body = body.substr(0, fold_end + 7);
    }
    // The slice keeps its lines: it starts on the line <CMML> or the last slice ended on.
    // Foldkit's own folds are read without building an XML document (read_plain_folds: it accepts
    // no markup that plain_body refuses); the first slice, which holds the title, and any slice
    // out of that shape are read as XML.
    if (first || !detail::read_plain_folds(body, line, reading.folds)) {
      if (!plain_body(body)) return std::nullopt;
      const std::string piece = (first ? head : std::string()) + "<CMML>" + std::string(body) + "</CMML>";
      try {
        const detail::XmlInput in(piece, name, first ? 1 : line);
        reading.read(in, in.root("CMML"));
      } catch (const ParseError&) {
        return std::nullopt;  // the whole file's reading says what is wrong, and where
      }
    }
    line += static_cast<int>(std::count(body.begin(), body.end(), '\n'));
    pending.consume(body.size());
  }
  return geometry::make_sequence(std::move(reading.title), std::move(reading.folds));
}

// A Pull over `text`, a piece at a time.
Pull pull_from(const std::string& text) {
  return [&text, at = std::size_t(0)](std::string& buffer) mutable {
    if (at >= text.size()) return false;
    const std::size_t n = std::min(kPullBytes, text.size() - at);
    buffer.append(text, at, n);
    at += n;
    return true;
  };
}

geometry::FoldSequence parse_cmml_whole(const std::string& text, const std::string& name) {
  detail::XmlInput in(text, name);
  CmmlReading reading;
  reading.read(in, in.root("CMML"));
  return geometry::make_sequence(std::move(reading.title), std::move(reading.folds));
}

// The text of `sequence` handed to `sink` about a megabyte at a time: write_cmml gathers it,
// write_cmml_file streams it to the file, so that the two write the same bytes.
void emit_cmml(const geometry::FoldSequence& sequence, const std::function<void(std::string_view)>& sink) {
  constexpr std::size_t kFlushBytes = std::size_t(1) << 20;
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<CMML>\n";
  out += "  <Title>" + detail::escape_xml(sequence.title) + "</Title>\n";
  for (const auto& event : sequence.events) {
    char number[16];
    const std::size_t number_size = static_cast<std::size_t>(std::to_chars(number, number + sizeof number, event.number).ptr - number);
    for (const auto& f : event.folds) {
      // Appended piece by piece: no temporary string per fold (a plan at Miura 40 × 40 writes
      // 565,000 of them).
      char id[16];
      const std::size_t id_size = static_cast<std::size_t>(std::to_chars(id, id + sizeof id, f.joint_id).ptr - id);
      out += "  <Fold>\n    <EventNumber>";
      out.append(number, number_size);
      out += "</EventNumber>\n    <ID>";
      out.append(id, id_size);
      out += "</ID>\n    <FoldAngle>";
      append_angle(out, f);
      out += "</FoldAngle>\n    <Velocity>";
      append_speed(out, f);
      out += "</Velocity>\n  </Fold>\n";
      if (out.size() >= kFlushBytes) {
        sink(out);
        out.clear();
      }
    }
  }
  out += "</CMML>\n";
  sink(out);
}

}  // namespace

namespace detail {

std::optional<geometry::FoldSequence> parse_cmml_sliced(const std::string& text, const std::string& name, std::size_t slice_bytes) {
  return read_sliced(pull_from(text), name, slice_bytes);
}

}  // namespace detail

// A CMML of thousands of folds (projected folding writes every crease at every step: 308,000
// <Fold> elements, 49 MB, for a Miura-ori 40 × 40) is read a slice of elements at a time, so that
// only one slice's document is in memory; the result is that of reading it whole, and a file the
// slices cannot read is read whole for its error.
geometry::FoldSequence parse_cmml(const std::string& text, const std::string& name) {
  if (text.size() >= kSlicedFrom)
    if (auto sequence = detail::parse_cmml_sliced(text, name, kSliceBytes)) return std::move(*sequence);
  return parse_cmml_whole(text, name);
}

// The file is pulled as the slices need it, plain or gzip-compressed alike, so that neither its
// text nor its compressed bytes are in memory whole; a small file, or one the slices decline
// (to be read whole for its error), is read whole as parse_cmml reads it.
geometry::FoldSequence read_cmml(const std::string& path) {
  detail::TextReader in(path);
  std::string head;
  while (head.size() < kSlicedFrom && in.read(head, kSlicedFrom - head.size())) {
  }
  if (head.size() < kSlicedFrom) return parse_cmml_whole(head, path);
  bool head_given = false;
  const Pull pull = [&](std::string& buffer) {
    if (head_given) return in.read(buffer, kPullBytes);
    head_given = true;
    buffer += head;
    head = std::string();  // its memory back: the slices hold the text from here on
    return true;
  };
  if (auto sequence = read_sliced(pull, path, kSliceBytes)) return std::move(*sequence);
  return parse_cmml_whole(read_file(path), path);
}

PendingCmmlFile::PendingCmmlFile(const std::string& path, const geometry::FoldSequence& sequence)
    : file_(std::make_unique<detail::AtomicFile>(path)) {
  emit_cmml(sequence, [this](std::string_view piece) { file_->write(piece); });
}

PendingCmmlFile::~PendingCmmlFile() = default;

void PendingCmmlFile::commit() { file_->commit(); }

void write_cmml_file(const std::string& path, const geometry::FoldSequence& sequence) { PendingCmmlFile(path, sequence).commit(); }

std::string write_cmml(const geometry::FoldSequence& sequence) {
  std::string text;
  emit_cmml(sequence, [&text](std::string_view piece) { text += piece; });
  return text;
}

}  // namespace foldkit::io
