#include "python/interruptible.h"

#include <signal.h>

#include <mutex>

namespace curdle::python {
namespace {

std::atomic<bool> interrupt_flag{false};  // lock-free: set from the signal handler
unsigned long main_thread_ident = 0;
// Watches may nest (a run inside a search's callback); the first installs, the last restores.
std::mutex watch_mutex;
int watches = 0;
struct sigaction python_handler {};

extern "C" void on_interrupt(int) { interrupt_flag.store(true); }

}  // namespace

void remember_main_thread() { main_thread_ident = PyThread_get_thread_ident(); }

InterruptWatch::InterruptWatch() {
  if (PyThread_get_thread_ident() != main_thread_ident) return;
  std::lock_guard lock(watch_mutex);
  if (watches++ == 0) {
    interrupt_flag.store(false);
    struct sigaction ours {};
    ours.sa_handler = on_interrupt;
    sigemptyset(&ours.sa_mask);
    sigaction(SIGINT, &ours, &python_handler);
  }
  installed_ = true;
}

InterruptWatch::~InterruptWatch() {
  if (!installed_) return;
  std::lock_guard lock(watch_mutex);
  if (--watches == 0) sigaction(SIGINT, &python_handler, nullptr);
}

std::optional<std::string> InterruptWatch::stop_reason() {
  if (interrupted()) return std::string("interrupted (Ctrl-C)");
  return std::nullopt;
}

bool InterruptWatch::interrupted() const { return installed_ && interrupt_flag.load(); }

const std::atomic<bool>& InterruptWatch::flag() const {
  return installed_ ? interrupt_flag : never_;
}

}  // namespace curdle::python
