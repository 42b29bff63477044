#pragma once
// The FOLD importer's view of the JSON text: checks nlohmann cannot make safely, parsing with
// errors located by line, and the start lines of values. Internal to foldkit_io.
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace foldkit::io::detail {

using json = nlohmann::json;

// Error texts may quote the input; keep them printable whatever bytes the file held.
std::string printable(std::string_view s);

// Rejects an empty text and nesting too deep to parse safely. Throws ParseError.
void check_text(std::string_view text, const std::string& name);

// Throws ParseError at the line of the fault.
json parse_json(const std::string& text, const std::string& name);

// Where a JSON value starts. node indexes LineMap's containers (-1: not kept).
struct Loc {
  int node = -1;
  int line = 1;
};

// Start lines of the JSON values, for messages about elements nlohmann has already parsed
// (it keeps no positions). Runs on text nlohmann accepted, so it need not recheck syntax.
class LineMap {
 public:
  explicit LineMap(std::string_view text);
  Loc root() const { return root_; }

  Loc member(const Loc& at, std::string_view key) const;
  Loc item(const Loc& at, std::size_t index) const;

 private:
  // Containers this deep or shallower keep their children's lines: enough for
  // file_frames[i].vertices_coords[j][k].
  static constexpr int kKeptDepth = 4;
  struct Node {
    bool object = false;
    std::vector<std::string> keys;  // raw (escapes kept); FOLD keys have none
    std::vector<Loc> children;
  };

  char peek() const;
  void skip_space();
  std::string string_token();
  Loc value(int depth);

  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
  std::vector<Node> nodes_;
  Loc root_;
};

}  // namespace foldkit::io::detail
