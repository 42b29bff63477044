#include "serve_paths.hpp"

namespace foldkit::apps {

namespace fs = std::filesystem;

RootedPaths::RootedPaths(const fs::path& root) {
  std::error_code ec;
  root_ = fs::canonical(root, ec);
  if (ec || !fs::is_directory(root_)) throw std::invalid_argument("--root " + root.string() + ": not an existing folder");
}

fs::path RootedPaths::checked(const std::string& relative) const {
  if (relative.find('\0') != std::string::npos) throw PathRefused("a path with a NUL character", false);
  const fs::path p(relative);
  if (p.is_absolute() || p.has_root_name() || p.has_root_directory())
    throw PathRefused(relative + ": absolute paths are refused; name files relative to the server's root", false);
  for (const auto& part : p)
    if (part == "..") throw PathRefused(relative + ": '..' is refused; files must stay under the server's root", false);
  return (root_ / p).lexically_normal();
}

bool RootedPaths::inside(const fs::path& resolved) const {
  const auto r = resolved.lexically_normal();
  auto a = root_.begin(), b = r.begin();
  for (; a != root_.end(); ++a, ++b)
    if (b == r.end() || *a != *b) return false;
  return true;
}

fs::path RootedPaths::existing(const fs::path& p, const std::string& relative, const char* noun) const {
  std::error_code ec;
  const fs::path resolved = fs::canonical(p, ec);
  if (ec) throw PathRefused(relative + ": no such " + noun + " under the server's root", true);
  if (!inside(resolved)) throw PathRefused(relative + ": a link that leads out of the server's root", false);
  return resolved;
}

fs::path RootedPaths::input(const std::string& relative) const {
  const fs::path resolved = existing(checked(relative), relative, "file");
  if (!fs::is_regular_file(resolved)) throw PathRefused(relative + ": not a file", false);
  return resolved;
}

fs::path RootedPaths::output(const std::string& relative) const {
  const fs::path p = checked(relative);
  if (p == root_ || relative.empty()) throw PathRefused("an output needs a file name", false);
  std::error_code ec;
  const fs::path parent = fs::canonical(p.parent_path(), ec);
  if (ec) throw PathRefused(relative + ": its folder does not exist under the server's root", true);
  if (!inside(parent)) throw PathRefused(relative + ": its folder is a link that leads out of the server's root", false);
  const fs::path target = parent / p.filename();
  const auto status = fs::symlink_status(target, ec);
  if (fs::is_symlink(status)) throw PathRefused(relative + ": a link; outputs are written as plain files", false);
  if (fs::is_directory(status)) throw PathRefused(relative + ": a folder, not a file", false);
  return target;
}

fs::path RootedPaths::output_folder(const std::string& relative) const {
  const fs::path p = checked(relative);
  std::error_code ec;
  if (fs::exists(fs::symlink_status(p, ec))) {
    const fs::path resolved = fs::canonical(p, ec);
    if (ec || !inside(resolved)) throw PathRefused(relative + ": a link that leads out of the server's root", false);
    if (!fs::is_directory(resolved)) throw PathRefused(relative + ": not a folder", false);
    // The verb writes files of its own naming in it, and a link among them would be written through.
    for (const auto& e : fs::directory_iterator(resolved, ec))
      if (e.is_symlink(ec)) throw PathRefused(relative + ": holds a link (" + e.path().filename().string() + "); outputs are never written through links", false);
    return resolved;
  }
  const fs::path parent = fs::canonical(p.parent_path(), ec);
  if (ec) throw PathRefused(relative + ": its folder does not exist under the server's root", true);
  if (!inside(parent)) throw PathRefused(relative + ": its folder is a link that leads out of the server's root", false);
  return parent / p.filename();
}

fs::path RootedPaths::folder(const std::string& relative) const {
  const fs::path resolved = existing(relative.empty() ? root_ : checked(relative), relative, "folder");
  if (!fs::is_directory(resolved)) throw PathRefused(relative + ": not a folder", false);
  return resolved;
}

std::string RootedPaths::relative(const fs::path& absolute) const {
  return absolute.lexically_normal().lexically_relative(root_).generic_string();
}

}  // namespace foldkit::apps
