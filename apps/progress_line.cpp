#include "progress_line.hpp"

#include <cstdio>
#include <iomanip>
#include <iostream>
#include <sstream>

#include <unistd.h>

namespace foldkit::apps {

namespace {
constexpr double kQuiet = 2.0;         // seconds before the first line
constexpr double kEveryTty = 1.0;      // seconds between redraws on a terminal
constexpr double kEveryLog = 5.0;      // seconds between lines otherwise
}  // namespace

ProgressLine::ProgressLine(std::string verb)
    : verb_(std::move(verb)), tty_(isatty(fileno(stderr)) != 0), start_(std::chrono::steady_clock::now()), last_(start_) {}

ProgressLine::~ProgressLine() {
  if (open_line_) std::cerr << '\n';
}

void ProgressLine::operator()(const geometry::Progress& p) {
  const auto now = std::chrono::steady_clock::now();
  const double elapsed = std::chrono::duration<double>(now - start_).count();
  if (elapsed < kQuiet || (shown_ && std::chrono::duration<double>(now - last_).count() < (tty_ ? kEveryTty : kEveryLog)))
    return;
  std::ostringstream s;
  s << verb_ << ": " << p.done;
  if (p.total > 0.0) s << '/' << p.total;
  s << ' ' << p.unit << ", " << std::fixed << std::setprecision(1) << elapsed << " s";
  if (p.closure_error >= 0.0) s << ", closure error " << std::scientific << std::setprecision(2) << p.closure_error << " rad";
  show(s.str());
}

void ProgressLine::stage(const std::string& what) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  if (elapsed < kQuiet) return;
  std::ostringstream s;
  s << verb_ << ": " << what << ", " << std::fixed << std::setprecision(1) << elapsed << " s";
  show(s.str());
}

void ProgressLine::show(const std::string& text) {
  if (tty_) {
    std::cerr << "\r\033[K" << text << std::flush;
    open_line_ = true;
  } else {
    std::cerr << text << '\n';
  }
  shown_ = true;
  last_ = std::chrono::steady_clock::now();
}

geometry::ProgressFn ProgressLine::callback() {
  return [this](const geometry::Progress& p) { (*this)(p); };
}

}  // namespace foldkit::apps
