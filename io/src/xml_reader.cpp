#include "foldkit/io/xml_reader.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string_view>
#include <utility>

#include <tinyxml2.h>

#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"
#include "text_lines.hpp"

namespace foldkit::io::detail {
namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
  while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
  return s;
}

void check_no_attributes(const XmlInput& in, const tinyxml2::XMLElement& e) {
  if (const auto* a = e.FirstAttribute())
    in.fail(e, std::string("unexpected attribute '") + a->Name() + "' on <" + e.Name() + ">");
}

// The UTF-8 sequence at s[i]: its length and code point, or 0 when it is not valid UTF-8
// (truncated, overlong, a surrogate U+D800–DFFF, or beyond U+10FFFF).
std::size_t decode_utf8(std::string_view s, std::size_t i, char32_t& cp) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) {
    cp = b0;
    return 1;
  }
  std::size_t len = 0;
  char32_t min = 0;
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    len = 2, cp = b0 & 0x1Fu, min = 0x80;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    len = 3, cp = b0 & 0x0Fu, min = 0x800;
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    len = 4, cp = b0 & 0x07u, min = 0x10000;
  } else {
    return 0;  // a continuation byte, an overlong lead (C0, C1) or F5–FF
  }
  if (s.size() - i < len) return 0;
  for (std::size_t k = 1; k < len; ++k) {
    if ((byte(i + k) & 0xC0u) != 0x80u) return 0;
    cp = (cp << 6) | (byte(i + k) & 0x3Fu);
  }
  if (cp < min || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
  return len;
}

// XML 1.0 `Char`: tab, LF, CR, and U+0020 onwards except surrogates, U+FFFE and U+FFFF.
bool xml_char(char32_t c) {
  return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD) ||
         (c >= 0x10000 && c <= 0x10FFFF);
}

std::string code_point_name(char32_t c) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(c));
  return buf;
}


// First offset of `text` that is not valid UTF-8 or not an XML character, with the complaint.
std::optional<std::pair<std::size_t, std::string>> bad_character(std::string_view text) {
  for (std::size_t i = 0; i < text.size();) {
    char32_t cp = 0;
    const std::size_t len = decode_utf8(text, i, cp);
    if (len == 0) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(text[i])));
      return std::pair{i, std::string("not valid UTF-8 (byte ") + buf + "): foldkit reads UTF-8 only"};
    }
    if (!xml_char(cp)) return std::pair{i, "character " + code_point_name(cp) + " is not allowed in XML"};
    i += len;
  }
  return std::nullopt;
}

// The encoding named by the text of an XML declaration ("xml version=… encoding=…"), if any.
std::optional<std::string> declared_encoding(std::string_view decl) {
  const auto at = decl.find("encoding");
  if (at == std::string_view::npos) return std::nullopt;
  std::string_view rest = trim(decl.substr(at + 8));
  if (rest.empty() || rest.front() != '=') return std::nullopt;
  rest = trim(rest.substr(1));
  if (rest.empty() || (rest.front() != '"' && rest.front() != '\'')) return std::nullopt;
  const auto close = rest.find(rest.front(), 1);
  return std::string(rest.substr(1, close == std::string_view::npos ? std::string_view::npos : close - 1));
}

bool is_utf8_name(const std::string& encoding) {
  std::string lower;
  for (char c : encoding) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower == "utf-8";
}

std::string unsupported_encoding(const std::string& encoding) {
  return "encoding '" + encoding.substr(0, 40) + "' is not supported: convert the file to UTF-8";
}

// Every numeric character reference (&#N; or &#xN;) outside comments, CDATA sections and
// processing instructions must name an XML character: tinyxml2 decodes &#xD800; into bytes
// that are not UTF-8, and drops or truncates at others (&#0;, &#x200000;).
std::optional<std::pair<std::size_t, std::string>> bad_reference(std::string_view text) {
  static const std::pair<std::string_view, std::string_view> skipped[] = {
      {"<!--", "-->"}, {"<![CDATA[", "]]>"}, {"<?", "?>"}};
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '<') {
      for (const auto& [open, close] : skipped) {
        if (text.compare(i, open.size(), open) != 0) continue;
        const auto end = text.find(close, i + open.size());
        if (end == std::string_view::npos) return std::nullopt;  // unterminated: tinyxml2 reports it
        i = end + close.size() - 1;
        break;
      }
      continue;
    }
    if (text[i] != '&' || text.compare(i, 2, "&#") != 0) continue;
    std::size_t j = i + 2;
    const bool hex = j < text.size() && text[j] == 'x';
    if (hex) ++j;
    const std::size_t digits = j;
    std::uint64_t value = 0;
    for (; j < text.size(); ++j) {
      const char c = text[j];
      int digit = -1;
      if (c >= '0' && c <= '9') digit = c - '0';
      else if (hex && c >= 'a' && c <= 'f') digit = c - 'a' + 10;
      else if (hex && c >= 'A' && c <= 'F') digit = c - 'A' + 10;
      if (digit < 0) break;
      value = std::min<std::uint64_t>(value * (hex ? 16u : 10u) + static_cast<unsigned>(digit), 0x7FFFFFFFu);
    }
    if (j == digits || j >= text.size() || text[j] != ';') continue;  // malformed: tinyxml2's call
    if (!xml_char(static_cast<char32_t>(value)))
      return std::pair{i, "character reference '" + std::string(text.substr(i, std::min<std::size_t>(j + 1 - i, 20))) +
                              "' is not an allowed XML character"};
  }
  return std::nullopt;
}

}  // namespace

XmlInput::~XmlInput() = default;

XmlInput::XmlInput(const std::string& text, std::string name, int first_line)
    : doc_(std::make_unique<tinyxml2::XMLDocument>(true, tinyxml2::PRESERVE_WHITESPACE)), name_(std::move(name)),
      line_offset_(first_line - 1) {
  if (const auto nul = text.find('\0'); nul != std::string::npos)
    fail(line_at(text, nul), "contains NUL bytes: not an XML text file");
  // The declaration first: a Latin-1 file is better told so than pointed at its first byte.
  std::string_view head(text);
  if (head.compare(0, 3, "\xEF\xBB\xBF") == 0) head.remove_prefix(3);
  if (head.compare(0, 5, "<?xml") == 0 && head.size() > 5 && is_space(head[5]))
    if (const auto end = head.find("?>"); end != std::string_view::npos)
      if (auto enc = declared_encoding(head.substr(2, end - 2)); enc && !is_utf8_name(*enc)) fail(1, unsupported_encoding(*enc));
  if (auto bad = bad_character(text)) fail(line_at(text, bad->first), bad->second);
  if (auto bad = bad_reference(text)) fail(line_at(text, bad->first), bad->second);
  if (doc_->Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    std::string what = doc_->ErrorStr() ? doc_->ErrorStr() : "XML syntax error";
    // tinyxml2's message repeats the line as "line=N"; keep the part that says what is wrong.
    if (auto pos = what.find(" Line number"); pos != std::string::npos) what.resize(pos);
    int line = doc_->ErrorLineNum();
    if (doc_->ErrorID() == tinyxml2::XML_ERROR_EMPTY_DOCUMENT) {
      what = "the file is empty";
      line = 1;
    }
    if (doc_->ErrorID() == tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED) what = "elements are nested too deeply";
    fail(line, (line == 1 && what == "the file is empty" ? "" : "invalid XML: ") + what);
  }
  check_decoded(*doc_);
}

void XmlInput::check_decoded(const tinyxml2::XMLNode& node) const {
  for (const tinyxml2::XMLNode* n = node.FirstChild(); n; n = n->NextSibling()) {
    if (const auto* decl = n->ToDeclaration()) {
      if (auto enc = declared_encoding(decl->Value() ? decl->Value() : ""); enc && !is_utf8_name(*enc))
        fail(*n, unsupported_encoding(*enc));
    } else if (const auto* t = n->ToText()) {
      // After tinyxml2 has decoded entities, the text must still be UTF-8 XML characters.
      if (auto bad = bad_character(t->Value() ? t->Value() : "")) fail(*n, "decoded text: " + bad->second);
    } else if (n->ToElement()) {
      check_decoded(*n);
    }
  }
}

const tinyxml2::XMLElement& XmlInput::root(const char* expected) const {
  const tinyxml2::XMLElement* r = doc_->RootElement();
  if (!r) fail(1, std::string("no <") + expected + "> element");
  if (std::strcmp(r->Name(), expected) != 0)
    fail(*r, std::string("the root element is <") + r->Name() + ">, expected <" + expected + ">");
  if (r->NextSiblingElement()) fail(*r->NextSiblingElement(), "a second root element");
  return *r;
}

void XmlInput::fail(int line, const std::string& message) const { throw ParseError(name_, line + line_offset_, message); }

void XmlInput::fail(const tinyxml2::XMLNode& at, const std::string& message) const { fail(at.GetLineNum(), message); }

int XmlInput::line(const tinyxml2::XMLNode& node) const { return node.GetLineNum() + line_offset_; }

std::string XmlInput::leaf_text(const tinyxml2::XMLElement& e) const {
  check_no_attributes(*this, e);
  if (const auto* child = e.FirstChildElement())
    fail(*child, std::string("<") + e.Name() + "> must hold text, not the element <" + child->Name() + ">");
  // The XML value: every text node and CDATA section in order, comments left out.
  std::string text;
  for (const tinyxml2::XMLNode* n = e.FirstChild(); n; n = n->NextSibling())
    if (const auto* t = n->ToText(); t && t->Value()) text += t->Value();
  return std::string(trim(text));
}

std::vector<const tinyxml2::XMLElement*> XmlInput::children(const tinyxml2::XMLElement& e) const {
  check_no_attributes(*this, e);
  std::vector<const tinyxml2::XMLElement*> out;
  for (const tinyxml2::XMLNode* n = e.FirstChild(); n; n = n->NextSibling()) {
    if (const auto* el = n->ToElement())
      out.push_back(el);
    else if (const auto* text = n->ToText(); text && text->Value() && !blank(text->Value()))
      fail(*n, std::string("unexpected text inside <") + e.Name() + ">");
  }
  return out;
}

std::vector<double> XmlInput::numbers(const tinyxml2::XMLElement& e) const {
  NumberList list = parse_numbers(leaf_text(e));
  if (!list.error.empty()) fail(e, std::string("<") + e.Name() + ">: " + list.error);
  return list.values;
}

std::vector<double> XmlInput::numbers(const tinyxml2::XMLElement& e, std::size_t count) const {
  const std::vector<double> values = numbers(e);
  const std::string tag = std::string("<") + e.Name() + ">";
  if (values.size() != count)
    fail(e, tag + (count == 1 ? " must hold one number" : " needs " + std::to_string(count) + " numbers") + ", found " +
                std::to_string(values.size()));
  return values;
}

int XmlInput::integer(const tinyxml2::XMLElement& e, const std::string& expected) const {
  const std::string text = leaf_text(e);
  auto v = parse_int(text);
  if (!v) fail(e, std::string("<") + e.Name() + "> must be " + expected + ", found '" + text.substr(0, 40) + "'");
  return *v;
}

const tinyxml2::XMLElement& XmlInput::only_child(const tinyxml2::XMLElement& parent, const char* tag) const {
  const tinyxml2::XMLElement* found = nullptr;
  for (const auto* c : children(parent)) {
    if (std::strcmp(c->Name(), tag) != 0) continue;
    if (found) fail(*c, std::string("<") + parent.Name() + "> has more than one <" + tag + ">");
    found = c;
  }
  if (!found) fail(parent, std::string("<") + parent.Name() + "> has no <" + tag + ">");
  return *found;
}

bool has_name(const tinyxml2::XMLElement* e, const char* tag) { return std::strcmp(e->Name(), tag) == 0; }

std::string escape_xml(const std::string& text) {
  static const char kReplacement[] = "\xEF\xBF\xBD";  // U+FFFD
  std::string out;
  for (std::size_t i = 0; i < text.size();) {
    char32_t cp = 0;
    const std::size_t len = decode_utf8(text, i, cp);
    if (len == 0 || !xml_char(cp)) {
      // Bytes that are not UTF-8, and characters XML 1.0 forbids (controls, U+FFFE, U+FFFF),
      // can never appear in a well-formed file, not even as references.
      out += kReplacement;
      i += len == 0 ? 1 : len;
      continue;
    }
    switch (text[i]) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\r': out += "&#13;"; break;  // a raw CR would be read back as LF
      default: out.append(text, i, len);
    }
    i += len;
  }
  return out;
}

}  // namespace foldkit::io::detail
