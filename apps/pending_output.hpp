#pragma once
// A verb's CMML written on the other core while the simulator replays it, and put at its path
// only when the replay accepts it (`foldkit fold`, `foldkit plan`).
#include <exception>
#include <functional>
#include <future>
#include <memory>
#include <string>

#include "foldkit/geometry/fold_sequence.hpp"
#include "foldkit/io/cmml.hpp"

namespace foldkit::apps {

class PendingOutput {
 public:
  explicit PendingOutput(std::string path) : path_(std::move(path)) {}

  // For the options' sequence_ready: starts writing the sequence to a temporary beside the path
  // on another thread. The algorithm waits for the returned future before its result (and the
  // sequence in it) moves, so the sequence is read in place, not copied.
  std::function<std::future<void>(const geometry::FoldSequence&)> starter();

  // Puts the file at its path: the temporary written meanwhile, or `sequence` written now when
  // writing never started. Write errors surface here, where writing after the replay raised them.
  // @throws io::WriteError (or what io::write_cmml_file throws)
  void commit(const geometry::FoldSequence& sequence);

 private:
  std::string path_;
  bool started_ = false;
  std::unique_ptr<io::PendingCmmlFile> file_;  // written, not yet at its path
  std::exception_ptr error_;                   // why it could not be written
};

}  // namespace foldkit::apps
