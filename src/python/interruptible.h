// Engine work run from Python: the GIL released while it runs, so that other Python threads go
// on, and Ctrl-C stopping it at its next stop point (curdle/stop.h) with KeyboardInterrupt.
#pragma once

#include <pybind11/pybind11.h>

#include <atomic>
#include <optional>
#include <string>
#include <utility>

#include "app/stopping.h"

namespace curdle::python {

// While it lives, SIGINT sets a flag instead of running Python's handler (which cannot run
// while the GIL is released); the handler is put back after. Only on Python's main thread,
// where Python receives signals: elsewhere the flag is never set.
class InterruptWatch : public app::StopRule {
 public:
  InterruptWatch();
  ~InterruptWatch() override;
  InterruptWatch(const InterruptWatch&) = delete;
  InterruptWatch& operator=(const InterruptWatch&) = delete;
  std::optional<std::string> stop_reason() override;
  bool interrupted() const;
  // For work that takes a cancel flag of its own (the seed search).
  const std::atomic<bool>& flag() const;

 private:
  bool installed_ = false;
  std::atomic<bool> never_{false};  // the flag off the main thread
};

// Remembers Python's main thread; call once when the module is imported.
void remember_main_thread();

// Runs work(watch) without the GIL under an InterruptWatch. A run interrupted, stopped or not,
// raises KeyboardInterrupt; other exceptions pass on to pybind11's translators.
template <class F>
auto run_interruptible(F&& work) {
  InterruptWatch watch;
  std::optional<decltype(work(watch))> result;
  try {
    pybind11::gil_scoped_release release;
    app::StopScope scope(watch);
    result.emplace(std::forward<F>(work)(watch));
  } catch (const app::WorkStopped&) {
    if (!watch.interrupted()) throw;
  }
  if (watch.interrupted()) {
    PyErr_SetNone(PyExc_KeyboardInterrupt);
    throw pybind11::error_already_set();
  }
  return std::move(*result);
}

}  // namespace curdle::python
