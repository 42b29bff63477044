#pragma once
#include <string>

namespace foldkit::test {

std::string data_path(const std::string& relative);      // test/data/<relative>
std::string fixture_path(const std::string& relative);   // ../shared/fixtures/<relative>
bool fixtures_available();
std::string cli_path();                                   // the built foldkit binary
// A fresh empty directory under the system temp folder, removed at exit.
std::string temp_dir();

}  // namespace foldkit::test
