#pragma once
#include <chrono>
#include <string>

#include "foldkit/geometry/progress.hpp"

namespace foldkit::apps {

// The one way a verb reports a long run on stderr (stdout stays for --json): nothing for the
// first two seconds, then a line at most once a second, redrawn in place on a terminal and one
// line every five seconds otherwise (logs, CI): "simulate: 164/300 events, 12.3 s, closure error 1.2e-05 rad".
class ProgressLine {
 public:
  explicit ProgressLine(std::string verb);
  ~ProgressLine();
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void operator()(const geometry::Progress& p);
  // A callback for the libraries' options; valid while this object lives.
  geometry::ProgressFn callback();
  // A stage with no count ("planning with RRTConnect"), shown under the same rules.
  void stage(const std::string& what);  // also quiet for the first two seconds

 private:
  void show(const std::string& text);

  std::string verb_;
  bool tty_;
  std::chrono::steady_clock::time_point start_, last_;
  bool shown_ = false;
  bool open_line_ = false;  // a redrawn line waits for its newline
};

}  // namespace foldkit::apps
