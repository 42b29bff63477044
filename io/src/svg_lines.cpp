// Origami Simulator's SVG convention read into lines (drawn_lines.hpp): the elements that draw
// straight lines, their transforms, stroke colours and opacities. Hand-written on tinyxml2
// (through XmlInput, which gives every node its line): no SVG library in Debian exposes the
// element lines and the unrendered geometry a crease pattern needs (librsvg and resvg rasterise).
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include <tinyxml2.h>

#include "foldkit/io/atomic_write.hpp"
#include "foldkit/io/drawn_lines.hpp"
#include "foldkit/io/parse_error.hpp"
#include "foldkit/io/xml_reader.hpp"

namespace foldkit::io {

namespace {

using geometry::Vec2;

// x' = a x + c y + e, y' = b x + d y + f (SVG's matrix(a b c d e f)).
struct Affine {
  double a = 1, b = 0, c = 0, d = 1, e = 0, f = 0;
  Vec2 operator()(const Vec2& p) const { return {a * p.x() + c * p.y() + e, b * p.x() + d * p.y() + f}; }
  Affine then(const Affine& m) const {  // this first, then m
    return {m.a * a + m.c * b, m.b * a + m.d * b, m.a * c + m.c * d, m.b * c + m.d * d, m.a * e + m.c * f + m.e,
            m.b * e + m.d * f + m.f};
  }
};

// What a node passes to its children: the transform to the file's coordinates and the paint.
struct Context {
  Affine to_file;
  std::optional<std::string> stroke;  // inherited
  double stroke_opacity = 1.0;        // inherited
  double opacity = 1.0;               // the product of the ancestors' opacities
};

// SVG's number lists: numbers separated by white space and/or one comma, where a sign or a
// second decimal point also starts a number ("1.5.5" is 1.5 and .5).
class Numbers {
 public:
  Numbers(std::string_view text, const detail::XmlInput& in, int line) : s_(text), in_(in), line_(line) {}
  void skip() {
    while (i_ < s_.size() && (std::isspace(static_cast<unsigned char>(s_[i_])) || s_[i_] == ',')) ++i_;
  }
  bool at_end() {
    skip();
    return i_ >= s_.size();
  }
  bool at_number() {
    skip();
    return i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || s_[i_] == '-' || s_[i_] == '+' || s_[i_] == '.');
  }
  char peek() {
    skip();
    return i_ < s_.size() ? s_[i_] : '\0';
  }
  char take() { return s_[i_++]; }
  double number() {
    skip();
    const std::size_t start = i_;
    if (i_ < s_.size() && (s_[i_] == '-' || s_[i_] == '+')) ++i_;
    bool point = false, digits = false;
    while (i_ < s_.size() && (std::isdigit(static_cast<unsigned char>(s_[i_])) || (s_[i_] == '.' && !point))) {
      point = point || s_[i_] == '.';
      digits = digits || s_[i_] != '.';
      ++i_;
    }
    if (digits && i_ < s_.size() && (s_[i_] == 'e' || s_[i_] == 'E')) {
      std::size_t j = i_ + 1;
      if (j < s_.size() && (s_[j] == '-' || s_[j] == '+')) ++j;
      if (j < s_.size() && std::isdigit(static_cast<unsigned char>(s_[j]))) {
        i_ = j;
        while (i_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_]))) ++i_;
      }
    }
    const std::string token(s_.substr(start, i_ - start));
    if (!digits) in_.fail(line_, "expected a number at '" + std::string(s_.substr(start, 12)) + "'");
    const double v = std::strtod(token.c_str(), nullptr);
    if (!std::isfinite(v)) in_.fail(line_, "the number " + token + " is not finite");
    return v;
  }

 private:
  std::string_view s_;
  std::size_t i_ = 0;
  const detail::XmlInput& in_;
  int line_;
};

std::string trimmed(std::string_view s) {
  const std::size_t b = s.find_first_not_of(" \t\r\n");
  if (b == std::string_view::npos) return "";
  return std::string(s.substr(b, s.find_last_not_of(" \t\r\n") - b + 1));
}

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// transform="translate(…) rotate(…) …": applied right to left, as SVG does.
Affine parse_transform(std::string_view text, const detail::XmlInput& in, int line) {
  Affine total;
  std::size_t i = 0;
  while (i < text.size()) {
    while (i < text.size() && (std::isspace(static_cast<unsigned char>(text[i])) || text[i] == ',')) ++i;
    if (i >= text.size()) break;
    const std::size_t open = text.find('(', i), close = text.find(')', i);
    if (open == std::string_view::npos || close == std::string_view::npos || close < open)
      in.fail(line, "transform: expected NAME(numbers) at '" + std::string(text.substr(i, 20)) + "'");
    const std::string fn = trimmed(text.substr(i, open - i));
    Numbers list(text.substr(open + 1, close - open - 1), in, line);
    std::vector<double> v;
    while (!list.at_end()) v.push_back(list.number());
    const auto need = [&](std::size_t lo, std::size_t hi) {
      if (v.size() < lo || v.size() > hi) in.fail(line, "transform: " + fn + " takes " + std::to_string(lo) + (lo == hi ? "" : " to " + std::to_string(hi)) + " numbers");
    };
    Affine m;
    const double deg = M_PI / 180.0;
    if (fn == "matrix") {
      need(6, 6);
      m = {v[0], v[1], v[2], v[3], v[4], v[5]};
    } else if (fn == "translate") {
      need(1, 2);
      m.e = v[0];
      m.f = v.size() > 1 ? v[1] : 0.0;
    } else if (fn == "scale") {
      need(1, 2);
      m.a = v[0];
      m.d = v.size() > 1 ? v[1] : v[0];
    } else if (fn == "rotate") {
      if (v.size() != 1 && v.size() != 3) in.fail(line, "transform: rotate takes 1 or 3 numbers");
      const double c = std::cos(v[0] * deg), s = std::sin(v[0] * deg);
      const double cx = v.size() == 3 ? v[1] : 0.0, cy = v.size() == 3 ? v[2] : 0.0;
      m = {c, s, -s, c, cx - c * cx + s * cy, cy - s * cx - c * cy};
    } else if (fn == "skewX") {
      need(1, 1);
      m.c = std::tan(v[0] * deg);
    } else if (fn == "skewY") {
      need(1, 1);
      m.b = std::tan(v[0] * deg);
    } else {
      in.fail(line, "transform: unknown function '" + fn + "'");
    }
    total = m.then(total);  // the list reads outermost first: the last one acts first
    i = close + 1;
  }
  return total;
}

// A stroke colour as Origami Simulator reads it; empty for none. Throws for anything else.
std::optional<LineKind> stroke_kind(const std::string& paint, const detail::XmlInput& in, int line) {
  std::string p = lower(trimmed(paint));
  std::array<int, 3> rgb{};
  const auto hex = [](char c) { return std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : c - 'a' + 10; };
  const auto valid_hex = [](const std::string& s) { return s.find_first_not_of("0123456789abcdef", 1) == std::string::npos; };
  if (p.empty() || p == "none" || p == "transparent") return std::nullopt;
  if (p[0] == '#' && p.size() == 4 && valid_hex(p)) {
    for (int k = 0; k < 3; ++k) rgb[k] = 17 * hex(p[1 + k]);
  } else if (p[0] == '#' && p.size() == 7 && valid_hex(p)) {
    for (int k = 0; k < 3; ++k) rgb[k] = 16 * hex(p[1 + 2 * k]) + hex(p[2 + 2 * k]);
  } else if (p.rfind("rgb(", 0) == 0 && p.back() == ')') {
    std::string inner = p.substr(4, p.size() - 5);
    const bool percent = inner.find('%') != std::string::npos;
    for (char& c : inner) if (c == '%') c = ' ';
    Numbers list(inner, in, line);
    for (int k = 0; k < 3; ++k) {
      if (list.at_end()) in.fail(line, "stroke " + paint + ": rgb() needs three numbers");
      const double v = list.number();
      rgb[k] = static_cast<int>(std::lround(percent ? v * 2.55 : v));
    }
  } else {
    static const std::pair<const char*, std::array<int, 3>> names[] = {
        {"black", {0, 0, 0}},       {"red", {255, 0, 0}},     {"blue", {0, 0, 255}},   {"lime", {0, 255, 0}},
        {"green", {0, 128, 0}},     {"yellow", {255, 255, 0}}, {"magenta", {255, 0, 255}}, {"fuchsia", {255, 0, 255}}};
    bool found = false;
    for (const auto& [n, c] : names)
      if (p == n) rgb = c, found = true;
    if (!found) in.fail(line, "stroke '" + paint + "' is not a colour this reader knows");
  }
  const auto is = [&](int r, int g, int b) { return rgb[0] == r && rgb[1] == g && rgb[2] == b; };
  if (is(0, 0, 0)) return LineKind::Border;
  if (is(255, 0, 0)) return LineKind::Mountain;
  if (is(0, 0, 255)) return LineKind::Valley;
  if (is(0, 255, 0) || is(0, 128, 0)) return LineKind::Cut;
  if (is(255, 255, 0)) return LineKind::Facet;
  if (is(255, 0, 255)) return LineKind::Hinge;
  in.fail(line, "stroke " + paint + " is none of Origami Simulator's line colours (black border, red mountain, blue "
                "valley, green cut, yellow facet, magenta hinge)");
}

class SvgWalker {
 public:
  SvgWalker(const detail::XmlInput& in, std::vector<DrawnLine>& out) : in_(in), out_(out) {}

  void walk(const tinyxml2::XMLElement& e, Context ctx) {
    const int line = in_.line(e);
    paint(e, ctx, line);
    const std::string tag = local_name(e.Name());
    if (tag == "svg" || tag == "g" || tag == "a" || tag == "switch") {
      for (const tinyxml2::XMLElement* c = e.FirstChildElement(); c; c = c->NextSiblingElement()) walk(*c, ctx);
      return;
    }
    if (tag != "line" && tag != "polyline" && tag != "polygon" && tag != "rect" && tag != "path") return;  // defs, text, …
    if (!ctx.stroke) return;
    const std::optional<LineKind> kind = stroke_kind(*ctx.stroke, in_, line);
    if (!kind) return;
    const double op = ctx.stroke_opacity * ctx.opacity;
    std::optional<double> target;
    if (*kind == LineKind::Mountain) target = op * M_PI;
    if (*kind == LineKind::Valley) target = -op * M_PI;
    const auto add = [&](const Vec2& p, const Vec2& q) {
      out_.push_back({ctx.to_file(p), ctx.to_file(q), *kind, target, line});
    };
    if (tag == "line") {
      add({number(e, "x1", line), number(e, "y1", line)}, {number(e, "x2", line), number(e, "y2", line)});
    } else if (tag == "rect") {
      const double x = number(e, "x", line), y = number(e, "y", line), w = number(e, "width", line), h = number(e, "height", line);
      if (!(w > 0 && h > 0)) in_.fail(line, "<rect> needs a positive width and height");
      const Vec2 c[4] = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
      for (int k = 0; k < 4; ++k) add(c[k], c[(k + 1) % 4]);
    } else if (tag == "polyline" || tag == "polygon") {
      const char* pts = e.Attribute("points");
      Numbers list(pts ? pts : "", in_, line);
      std::vector<Vec2> p;
      while (!list.at_end()) {
        const double x = list.number();
        if (list.at_end()) in_.fail(line, "<" + tag + "> points: an odd count of numbers");
        p.emplace_back(x, list.number());
      }
      for (std::size_t k = 0; k + 1 < p.size(); ++k) add(p[k], p[k + 1]);
      if (tag == "polygon" && p.size() > 2) add(p.back(), p.front());
    } else {
      path(e.Attribute("d") ? e.Attribute("d") : "", line, add);
    }
  }

 private:
  static std::string local_name(const char* name) {
    const std::string n(name);
    const std::size_t colon = n.find(':');
    return colon == std::string::npos ? n : n.substr(colon + 1);
  }

  double number(const tinyxml2::XMLElement& e, const char* attribute, int line) const {
    const char* text = e.Attribute(attribute);
    if (!text) return 0.0;  // SVG's default for every coordinate
    std::string t = trimmed(text);
    if (t.size() > 2 && t.compare(t.size() - 2, 2, "px") == 0) t.resize(t.size() - 2);
    Numbers list(t, in_, line);
    const double v = list.number();
    if (!list.at_end()) in_.fail(line, std::string(attribute) + "=\"" + text + "\" is not a number in user units");
    return v;
  }

  double fraction(const std::string& text, const char* what, int line) const {
    Numbers list(text, in_, line);
    const double v = list.number();
    if (!list.at_end() || !(v >= 0.0 && v <= 1.0)) in_.fail(line, std::string(what) + " " + text + " is not a number in [0, 1]");
    return v;
  }

  // The element's own presentation attributes and style, over what it inherits.
  void paint(const tinyxml2::XMLElement& e, Context& ctx, int line) const {
    std::vector<std::pair<std::string, std::string>> props;
    for (const char* name : {"stroke", "stroke-opacity", "opacity", "transform"})
      if (const char* v = e.Attribute(name)) props.emplace_back(name, v);
    if (const char* style = e.Attribute("style")) {
      std::string_view s(style);
      while (!s.empty()) {
        const std::size_t semi = std::min(s.find(';'), s.size());
        const std::string_view decl = s.substr(0, semi);
        const std::size_t colon = decl.find(':');
        if (colon != std::string_view::npos) props.emplace_back(lower(trimmed(decl.substr(0, colon))), trimmed(decl.substr(colon + 1)));
        s.remove_prefix(std::min(semi + 1, s.size()));
      }
    }
    for (const auto& [name, value] : props) {
      if (name == "stroke") ctx.stroke = value;
      if (name == "stroke-opacity") ctx.stroke_opacity = fraction(value, "stroke-opacity", line);
      if (name == "opacity") ctx.opacity *= fraction(value, "opacity", line);
      if (name == "transform") ctx.to_file = parse_transform(value, in_, line).then(ctx.to_file);
    }
  }

  template <class Add>
  void path(std::string_view d, int line, const Add& add) const {
    Numbers list(d, in_, line);
    Vec2 at = Vec2::Zero(), start = Vec2::Zero();
    char command = '\0';
    while (!list.at_end()) {
      if (!list.at_number()) {
        command = list.take();
        if (std::string_view("MmLlHhVvZz").find(command) == std::string_view::npos) {
          if (std::string_view("CcSsQqTtAa").find(command) != std::string_view::npos)
            in_.fail(line, std::string("path command '") + command + "' draws a curve: a crease pattern has straight lines only");
          in_.fail(line, std::string("path: unknown command '") + command + "'");
        }
        if (command == 'Z' || command == 'z') {
          if (at != start) add(at, start);
          at = start;
          continue;
        }
      } else if (command == '\0' || command == 'Z' || command == 'z') {
        in_.fail(line, "path: numbers before a command");
      }
      const bool rel = std::islower(static_cast<unsigned char>(command));
      Vec2 next = at;
      switch (std::tolower(static_cast<unsigned char>(command))) {
        case 'h': next.x() = list.number() + (rel ? at.x() : 0.0); break;
        case 'v': next.y() = list.number() + (rel ? at.y() : 0.0); break;
        default: {
          const double x = list.number(), y = list.number();
          next = rel ? Vec2(at.x() + x, at.y() + y) : Vec2(x, y);
        }
      }
      if (command == 'M' || command == 'm') {
        start = next;
        command = command == 'M' ? 'L' : 'l';  // further pairs after a moveto are linetos
      } else {
        add(at, next);
      }
      at = next;
    }
  }

  const detail::XmlInput& in_;
  std::vector<DrawnLine>& out_;
};

}  // namespace

std::vector<DrawnLine> parse_svg_lines(const std::string& text, const std::string& name) {
  const detail::XmlInput in(text, name);
  const tinyxml2::XMLElement* root = nullptr;
  try {
    root = &in.root("svg");
  } catch (const ParseError& e) {
    try {
      root = &in.root("svg:svg");  // a prefixed root, as some editors write it
    } catch (const ParseError&) {
      throw e;
    }
  }
  std::vector<DrawnLine> lines;
  SvgWalker(in, lines).walk(*root, Context{});
  return lines;
}

PatternFile read_svg_pattern(const std::string& path, const geometry::BuildOptions& options) {
  LineImportOptions o;
  o.build = options;
  return pattern_from_lines(parse_svg_lines(read_file(path), path), path, o);
}

}  // namespace foldkit::io
