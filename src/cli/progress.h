// Progress on a terminal for work that takes more than a second; silent in pipes and logs.
#pragma once

#include <chrono>
#include <string>

namespace curdle::cli {

class Progress {
 public:
  // `enabled` false: never shows anything (work done for the server, say).
  explicit Progress(std::string what, bool enabled = true);
  ~Progress();
  void update(double fraction);

 private:
  std::string what_;
  std::chrono::steady_clock::time_point start_;
  bool terminal_ = false;
  bool shown_ = false;
  int last_percent_ = -1;
};

}  // namespace curdle::cli

#include "app/observer.h"

namespace curdle::cli {

// A run's progress and notes on the terminal (notes on standard error).
class TerminalObserver : public app::RunObserver {
 public:
  std::unique_ptr<app::ProgressTask> begin(const std::string& what) override;
  void skipped(const std::string& output, uint64_t count, const std::string& unit,
               uint64_t limit) override;
  void not_installed(const std::string& output, const std::string& why) override;
};

}  // namespace curdle::cli
