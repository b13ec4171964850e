// Long work that can be stopped part-way. Layout builders and writers call stop_point() in
// their loops; whoever runs the work on this thread (the server: a request's time budget, a
// client that went away) installs a StopRule for as long as it runs, and stop_point throws
// WorkStopped once the rule says stop. Without a rule stop_point costs a thread-local read.
#pragma once

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

namespace curdle {

// The work was stopped; what() says why ("it ran past its 60 s budget").
class WorkStopped : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StopRule {
 public:
  virtual ~StopRule() = default;
  // Why the work must stop now, or nothing to go on. Asked now and then, not at every point.
  virtual std::optional<std::string> stop_reason() = 0;
};

// Installs `rule` for the work on this thread until destroyed (rules nest: the inner wins).
class StopScope {
 public:
  explicit StopScope(StopRule& rule);
  // The rule of work handed over from another thread (its current_stop_rule()), when it has
  // one; with none, this thread's rule stays as it is.
  explicit StopScope(StopRule* rule);
  ~StopScope();
  StopScope(const StopScope&) = delete;
  StopScope& operator=(const StopScope&) = delete;

 private:
  StopRule* outer_;
};

namespace detail {
struct StopState {
  StopRule* rule = nullptr;
  uint32_t countdown = 0;
};
inline thread_local StopState stop_state;
void ask_stop_rule();
}  // namespace detail

// The rule this thread's work runs under, or null: work handed to other threads installs it
// there too (a StopScope per task), so that it stops as this thread's would.
inline StopRule* current_stop_rule() { return detail::stop_state.rule; }

// A point where this thread's work may be stopped: throws WorkStopped when its rule says so.
// The rule is asked once every 256 points, so a loop may call it for every element.
inline void stop_point() {
  auto& s = detail::stop_state;
  if (s.rule && s.countdown-- == 0) detail::ask_stop_rule();
}

// The same, asking the rule at once: for loops whose steps are long (a batch of seeds).
inline void stop_point_now() {
  if (detail::stop_state.rule) detail::ask_stop_rule();
}

}  // namespace curdle
