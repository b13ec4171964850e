#include "cli/progress.h"

#include <unistd.h>

#include <cstdio>

namespace curdle::cli {

Progress::Progress(std::string what, bool enabled)
    : what_(std::move(what)),
      start_(std::chrono::steady_clock::now()),
      terminal_(enabled && ::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
  if (shown_) std::fprintf(stderr, "\r%s: done.          \n", what_.c_str());
}

void Progress::update(double fraction) {
  if (!terminal_) return;
  if (!shown_ && std::chrono::steady_clock::now() - start_ < std::chrono::seconds(1)) return;
  const int percent = static_cast<int>(fraction * 100);
  if (percent == last_percent_) return;
  last_percent_ = percent;
  shown_ = true;
  std::fprintf(stderr, "\r%s: %3d%%", what_.c_str(), percent);
  std::fflush(stderr);
}

void TerminalObserver::not_installed(const std::string& output, const std::string& why) {
  std::fprintf(stderr, "note: %s left out: %s\n", output.c_str(), why.c_str());
}

}  // namespace curdle::cli

namespace curdle::cli {
namespace {
class ProgressOnTerminal : public app::ProgressTask {
 public:
  explicit ProgressOnTerminal(const std::string& what) : progress_(what) {}
  void update(double fraction) override { progress_.update(fraction); }

 private:
  Progress progress_;
};
}  // namespace

std::unique_ptr<app::ProgressTask> TerminalObserver::begin(const std::string& what) {
  return std::make_unique<ProgressOnTerminal>(what);
}

void TerminalObserver::skipped(const std::string& output, uint64_t count, const std::string& unit,
                               uint64_t limit) {
  std::fprintf(stderr,
               "note: %s skipped: %llu %s is above %llu; name it with --outputs %s to write it "
               "anyway\n",
               output.c_str(), static_cast<unsigned long long>(count), unit.c_str(),
               static_cast<unsigned long long>(limit), output.c_str());
}

}  // namespace curdle::cli
