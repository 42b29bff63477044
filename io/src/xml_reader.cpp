#include "xml_reader.hpp"

#include <algorithm>
#include <cstring>

#include "foldkit/io/number_format.hpp"
#include "foldkit/io/parse_error.hpp"

namespace foldkit::io::detail {
namespace {

bool blank(const char* s) {
  for (; s && *s; ++s)
    if (*s != ' ' && *s != '\t' && *s != '\n' && *s != '\r') return false;
  return true;
}

void check_no_attributes(const XmlInput& in, const tinyxml2::XMLElement& e) {
  if (const auto* a = e.FirstAttribute())
    in.fail(e, std::string("unexpected attribute '") + a->Name() + "' on <" + e.Name() + ">");
}

}  // namespace

XmlInput::XmlInput(const std::string& text, std::string name) : doc_(true, tinyxml2::COLLAPSE_WHITESPACE), name_(std::move(name)) {
  if (const auto nul = text.find('\0'); nul != std::string::npos)
    fail(1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(nul), '\n')),
         "contains NUL bytes: not an XML text file");
  if (doc_.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    std::string what = doc_.ErrorStr() ? doc_.ErrorStr() : "XML syntax error";
    // tinyxml2's message repeats the line as "line=N"; keep the part that says what is wrong.
    if (auto pos = what.find(" Line number"); pos != std::string::npos) what.resize(pos);
    int line = doc_.ErrorLineNum();
    if (doc_.ErrorID() == tinyxml2::XML_ERROR_EMPTY_DOCUMENT) {
      what = "the file is empty";
      line = 1;
    }
    if (doc_.ErrorID() == tinyxml2::XML_ELEMENT_DEPTH_EXCEEDED) what = "elements are nested too deeply";
    fail(line, (line == 1 && what == "the file is empty" ? "" : "invalid XML: ") + what);
  }
}

const tinyxml2::XMLElement& XmlInput::root(const char* expected) const {
  const tinyxml2::XMLElement* r = doc_.RootElement();
  if (!r) fail(1, std::string("no <") + expected + "> element");
  if (std::strcmp(r->Name(), expected) != 0)
    fail(*r, std::string("the root element is <") + r->Name() + ">, expected <" + expected + ">");
  if (r->NextSiblingElement()) fail(*r->NextSiblingElement(), "a second root element");
  return *r;
}

void XmlInput::fail(int line, const std::string& message) const { throw ParseError(name_, line, message); }

void XmlInput::fail(const tinyxml2::XMLNode& at, const std::string& message) const { fail(at.GetLineNum(), message); }

std::string XmlInput::leaf_text(const tinyxml2::XMLElement& e) const {
  check_no_attributes(*this, e);
  if (const auto* child = e.FirstChildElement())
    fail(*child, std::string("<") + e.Name() + "> must hold text, not the element <" + child->Name() + ">");
  const char* t = e.GetText();
  return t ? std::string(t) : std::string();
}

std::vector<const tinyxml2::XMLElement*> XmlInput::children(const tinyxml2::XMLElement& e) const {
  check_no_attributes(*this, e);
  std::vector<const tinyxml2::XMLElement*> out;
  for (const tinyxml2::XMLNode* n = e.FirstChild(); n; n = n->NextSibling()) {
    if (const auto* el = n->ToElement())
      out.push_back(el);
    else if (const auto* text = n->ToText(); text && !blank(text->Value()))
      fail(*n, std::string("unexpected text inside <") + e.Name() + ">");
  }
  return out;
}

std::vector<double> XmlInput::numbers(const tinyxml2::XMLElement& e, std::size_t count) const {
  NumberList list = parse_numbers(leaf_text(e));
  const std::string tag = std::string("<") + e.Name() + ">";
  if (!list.error.empty()) fail(e, tag + ": " + list.error);
  if (list.values.size() != count)
    fail(e, tag + (count == 1 ? " must hold one number" : " needs " + std::to_string(count) + " numbers") + ", found " +
                std::to_string(list.values.size()));
  return list.values;
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
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  }
  return out;
}

}  // namespace foldkit::io::detail
