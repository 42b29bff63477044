#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

// tinyxml2 stays private to foldkit::io: a reader elsewhere (load cases in foldkit::analysis) that
// walks the elements includes <tinyxml2.h> and links tinyxml2 itself.
namespace tinyxml2 {
class XMLDocument;
class XMLElement;
class XMLNode;
}  // namespace tinyxml2

// Shared by foldkit's readers of XML formats in the style of PMML (PMML and CMML here, load cases
// in foldkit::analysis), so that all of them hold the same rules; not meant as a general API.
namespace foldkit::io::detail {

// A strictly read XML file: every problem is a ParseError at the line of the offending node.
// The input must be UTF-8 (any declared encoding other than UTF-8 is refused) and contain only
// XML 1.0 characters, raw or as character references.
class XmlInput {
 public:
  XmlInput(const std::string& text, std::string name);
  ~XmlInput();
  XmlInput(const XmlInput&) = delete;
  XmlInput& operator=(const XmlInput&) = delete;

  // The root element, which must be named `expected`.
  const tinyxml2::XMLElement& root(const char* expected) const;

  [[noreturn]] void fail(int line, const std::string& message) const;
  [[noreturn]] void fail(const tinyxml2::XMLNode& at, const std::string& message) const;

  // Text of an element that holds only text (no child elements, no attributes): all its text
  // and CDATA children joined, comments skipped, leading and trailing whitespace removed.
  std::string leaf_text(const tinyxml2::XMLElement& e) const;

  // Child elements of a container in order, after rejecting attributes and stray text.
  std::vector<const tinyxml2::XMLElement*> children(const tinyxml2::XMLElement& e) const;

  // Exactly `count` finite numbers (NaN, inf, 1e999 and garbage are errors).
  std::vector<double> numbers(const tinyxml2::XMLElement& e, std::size_t count) const;
  // As many finite numbers as the element holds.
  std::vector<double> numbers(const tinyxml2::XMLElement& e) const;
  double number(const tinyxml2::XMLElement& e) const { return numbers(e, 1)[0]; }

  // A whole number in int range; `expected` completes "<Tag> must be …" in the message.
  int integer(const tinyxml2::XMLElement& e, const std::string& expected) const;

  // The one child named `tag` (missing or repeated is an error).
  const tinyxml2::XMLElement& only_child(const tinyxml2::XMLElement& parent, const char* tag) const;

  const std::string& name() const { return name_; }

 private:
  void check_decoded(const tinyxml2::XMLNode& node) const;

  std::unique_ptr<tinyxml2::XMLDocument> doc_;
  std::string name_;
};

// Text for an XML element: markup characters escaped, CR as a reference, and anything that may
// not appear in an XML 1.0 UTF-8 file (bytes that are not UTF-8, controls other than tab, LF and
// CR, U+FFFE, U+FFFF) replaced by U+FFFD.
std::string escape_xml(const std::string& text);

bool has_name(const tinyxml2::XMLElement* e, const char* tag);

}  // namespace foldkit::io::detail
