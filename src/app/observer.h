// What a run tells its caller as it goes: progress of long steps, and notes. The command line
// shows them on a terminal; the server passes none.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

namespace curdle::app {

class ProgressTask {
 public:
  virtual ~ProgressTask() = default;
  virtual void update(double fraction) = 0;  // from 0 to 1
};

class RunObserver {
 public:
  virtual ~RunObserver() = default;
  // A long step begins; it ends when the task is destroyed.
  virtual std::unique_ptr<ProgressTask> begin(const std::string& what) = 0;
  // A default output left out for its size: `count` `unit` is above `limit`. Each shell says
  // how to ask for it anyway in its own words.
  virtual void skipped(const std::string& output, uint64_t count, const std::string& unit,
                       uint64_t limit) = 0;
  // A default output left out because this installation lacks what writes it; `why` says what
  // to install.
  virtual void not_installed(const std::string& output, const std::string& why) = 0;
};

}  // namespace curdle::app
