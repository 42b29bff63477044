#pragma once
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <sys/wait.h>

#include "test_paths.hpp"

namespace foldkit::test {

struct CliResult {
  int exit = -1;
  std::string out, err;
};

// Writes `content` to `name` in one temporary folder shared by the calling test program; returns its path.
inline std::string write_temp(const std::string& name, const std::string& content) {
  static const std::string dir = temp_dir();
  const std::string path = dir + "/" + name;
  std::ofstream(path, std::ios::binary) << content;
  return path;
}

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// Runs `foldkit ARGS` with a 60 s limit (a hang fails the test instead of blocking it).
inline CliResult foldkit(const std::vector<std::string>& args) {
  static const std::string dir = temp_dir();
  std::string cmd = "timeout 60 " + shell_quote(cli_path());
  for (const auto& a : args) cmd += " " + shell_quote(a);
  cmd += " >" + dir + "/out 2>" + dir + "/err";
  const int status = std::system(cmd.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, slurp(dir + "/out"), slurp(dir + "/err")};
}

}  // namespace foldkit::test
