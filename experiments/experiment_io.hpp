// Command line and output folder shared by the experiment programs (figN_* --out DIR --check).
#pragma once
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "foldkit/io/atomic_write.hpp"

namespace foldkit::experiments {

struct Args {
  std::string out;
  bool check = false;
};

// `usage` is printed on a bad argument (exit 2) and for --help (exit 0).
inline Args parse_args(int argc, char** argv, const std::string& default_out, const std::string& usage) {
  Args a{default_out, false};
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--check")) a.check = true;
    else if (!std::strcmp(argv[i], "--out") && i + 1 < argc) a.out = argv[++i];
    else if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
      std::cout << usage;
      std::exit(0);
    } else {
      std::cerr << argv[0] << ": unknown argument '" << argv[i] << "'\n" << usage;
      std::exit(2);
    }
  }
  return a;
}

// Writes DIR/name atomically, creating DIR; says where on stderr. A file that cannot be written
// ends the program with exit status 1.
inline void write_output(const Args& a, const std::string& name, const std::string& content) {
  const std::string path = (std::filesystem::path(a.out) / name).string();
  try {
    std::filesystem::create_directories(a.out);
    io::write_file_atomic(path, content);
  } catch (const std::exception& e) {
    std::cerr << path << ": cannot write: " << e.what() << '\n';
    std::exit(1);
  }
  std::cerr << "  wrote " << path << '\n';
}

// A number for Markdown tables and CSV: `digits` significant digits.
inline std::string num(double v, int digits = 4) {
  std::ostringstream s;
  s << std::setprecision(digits) << v;
  return s.str();
}

// Prints one check line on stderr and returns `ok`.
inline bool expect(bool ok, const std::string& what) {
  std::cerr << "  check: " << what << ": " << (ok ? "ok" : "FAILED") << '\n';
  return ok;
}

}  // namespace foldkit::experiments
