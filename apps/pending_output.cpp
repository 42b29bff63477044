#include "pending_output.hpp"

namespace foldkit::apps {

std::function<std::future<void>(const geometry::FoldSequence&)> PendingOutput::starter() {
  return [this](const geometry::FoldSequence& sequence) {
    started_ = true;
    return std::async(std::launch::async, [this, &sequence] {
      try {
        file_ = std::make_unique<io::PendingCmmlFile>(path_, sequence);
      } catch (...) {
        error_ = std::current_exception();
      }
    });
  };
}

void PendingOutput::commit(const geometry::FoldSequence& sequence) {
  if (!started_)
    io::write_cmml_file(path_, sequence);  // streamed: a large sequence's text is never whole in memory
  else if (error_)
    std::rethrow_exception(error_);
  else
    file_->commit();
}

}  // namespace foldkit::apps
