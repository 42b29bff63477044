#include "test_paths.hpp"

#include <cstdlib>
#include <filesystem>
#include <random>
#include <vector>

namespace foldkit::test {
namespace fs = std::filesystem;

std::string data_path(const std::string& relative) { return std::string(FOLDKIT_TEST_DATA) + "/" + relative; }

std::string fixture_path(const std::string& relative) {
  return std::string(FOLDKIT_SHARED_FIXTURES) + "/" + relative;
}

bool fixtures_available() { return fs::is_directory(FOLDKIT_SHARED_FIXTURES); }

std::string cli_path() { return FOLDKIT_CLI; }

namespace {
struct TempDirs {
  std::vector<fs::path> dirs;
  ~TempDirs() {
    std::error_code ec;
    for (const auto& d : dirs) fs::remove_all(d, ec);
  }
};
TempDirs temp_dirs;
}  // namespace

std::string temp_dir() {
  std::random_device rd;
  for (;;) {
    fs::path p = fs::temp_directory_path() / ("foldkit-test-" + std::to_string(rd()));
    if (fs::create_directory(p)) {
      temp_dirs.dirs.push_back(p);
      return p.string();
    }
  }
}

}  // namespace foldkit::test
