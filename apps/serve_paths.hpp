#pragma once
// Files a `foldkit serve` request may name: paths relative to the server's root, which must stay
// inside it (no absolute paths, no "..", no symbolic link that leads out).
#include <filesystem>
#include <stdexcept>
#include <string>

namespace foldkit::apps {

// A path a request may not use: outside the root, absent, or of the wrong kind (HTTP 400/404).
struct PathRefused : std::runtime_error {
  PathRefused(const std::string& what, bool is_missing) : std::runtime_error(what), missing(is_missing) {}
  bool missing;  ///< the path is inside the root but names nothing (404 rather than 400)
};

class RootedPaths {
 public:
  // `root` must be an existing directory; it is resolved once (symbolic links included).
  explicit RootedPaths(const std::filesystem::path& root);

  const std::filesystem::path& root() const { return root_; }

  // An existing regular file inside the root, resolved through any links.
  std::filesystem::path input(const std::string& relative) const;
  // A file to write: its folder exists inside the root, and the path itself is not a link nor a
  // folder (a verb writes it through a temporary file and a rename).
  std::filesystem::path output(const std::string& relative) const;
  // A folder to write into (created by the verb if absent): as output(), but a folder.
  std::filesystem::path output_folder(const std::string& relative) const;
  // An existing folder inside the root ("" is the root).
  std::filesystem::path folder(const std::string& relative) const;
  // `absolute` (inside the root) as the request would name it.
  std::string relative(const std::filesystem::path& absolute) const;

 private:
  std::filesystem::path checked(const std::string& relative) const;  // lexically inside, not resolved
  // `p` resolved through links, which must exist and stay inside (`noun` names it in messages).
  std::filesystem::path existing(const std::filesystem::path& p, const std::string& relative, const char* noun) const;
  bool inside(const std::filesystem::path& resolved) const;

  std::filesystem::path root_;
};

}  // namespace foldkit::apps
