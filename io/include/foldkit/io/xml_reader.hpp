#pragma once
/// @file
/// The strict XML reading shared by foldkit's readers of PMML-style formats (an implementation
/// detail of foldkit::io and foldkit::analysis, not a general API).
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

/// Shared by foldkit's readers of XML formats in the style of PMML (PMML and CMML here, load cases
/// in foldkit::analysis), so that all of them hold the same rules; not meant as a general API.
namespace foldkit::io::detail {

/// A strictly read XML file: every problem is a ParseError at the line of the offending node.
/// The input must be UTF-8 (any declared encoding other than UTF-8 is refused) and contain only
/// XML 1.0 characters, raw or as character references.
class XmlInput {
 public:
  /// Parses `text`; `name` (a file name) locates every error.
  /// @param text        the XML text
  /// @param name        the file name of every error
  /// @param first_line  the line of the file `text` starts on, when it is a slice of a file
  ///                    (every line reported and returned by line() counts from there)
  /// @throws ParseError for NUL bytes, a declared encoding other than UTF-8, bytes that are not
  ///         UTF-8 XML characters, bad character references, or an XML syntax error
  XmlInput(const std::string& text, std::string name, int first_line = 1);
  ~XmlInput();  ///< Frees the parsed document.
  XmlInput(const XmlInput&) = delete;             ///< Not copyable.
  XmlInput& operator=(const XmlInput&) = delete;  ///< Not copyable.

  /// The root element, which must be named `expected` and be the only one.
  /// @throws ParseError otherwise
  const tinyxml2::XMLElement& root(const char* expected) const;

  /// Throws ParseError(name(), line, message).
  [[noreturn]] void fail(int line, const std::string& message) const;
  /// Throws ParseError(name(), line of `at`, message).
  [[noreturn]] void fail(const tinyxml2::XMLNode& at, const std::string& message) const;

  /// Text of an element that holds only text (no child elements, no attributes): all its text
  /// and CDATA children joined, comments skipped, leading and trailing whitespace removed.
  /// @throws ParseError for an attribute or a child element
  std::string leaf_text(const tinyxml2::XMLElement& e) const;

  /// Child elements of a container in order, after rejecting attributes and stray text.
  /// @throws ParseError for an attribute or non-blank text
  std::vector<const tinyxml2::XMLElement*> children(const tinyxml2::XMLElement& e) const;

  /// Exactly `count` finite numbers (NaN, inf, 1e999 and garbage are errors).
  /// @throws ParseError otherwise
  std::vector<double> numbers(const tinyxml2::XMLElement& e, std::size_t count) const;
  /// As many finite numbers as the element holds.
  /// @throws ParseError for a token that is not a finite number
  std::vector<double> numbers(const tinyxml2::XMLElement& e) const;
  /// Exactly one finite number.
  /// @throws ParseError otherwise
  double number(const tinyxml2::XMLElement& e) const { return numbers(e, 1)[0]; }

  /// A whole number in int range; `expected` completes `<Tag> must be …` in the message.
  /// @throws ParseError otherwise
  int integer(const tinyxml2::XMLElement& e, const std::string& expected) const;

  /// The one child named `tag`.
  /// @throws ParseError when it is missing or repeated
  const tinyxml2::XMLElement& only_child(const tinyxml2::XMLElement& parent, const char* tag) const;

  /// The file name given to the constructor.
  const std::string& name() const { return name_; }
  /// The line of the file `node` is on.
  int line(const tinyxml2::XMLNode& node) const;

 private:
  void check_decoded(const tinyxml2::XMLNode& node) const;

  std::unique_ptr<tinyxml2::XMLDocument> doc_;
  std::string name_;
  int line_offset_ = 0;  // the lines of the file before the text parsed
};

/// Text for an XML element: markup characters escaped, CR as a reference, and anything that may
/// not appear in an XML 1.0 UTF-8 file (bytes that are not UTF-8, controls other than tab, LF and
/// CR, U+FFFE, U+FFFF) replaced by U+FFFD.
std::string escape_xml(const std::string& text);

/// Whether element `e` (not null) is named `tag`.
bool has_name(const tinyxml2::XMLElement* e, const char* tag);

}  // namespace foldkit::io::detail
