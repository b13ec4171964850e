#include "cli/interrupt.h"

#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <cstdio>
#include <thread>

#include "app/output_sink.h"

namespace curdle::cli {

void remove_staged_files_on_interrupt() {
  static sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::thread([] {
    int received = 0;
    if (sigwait(&signals, &received) != 0) return;
    app::remove_staged_files_for_exit();
    std::fprintf(stderr, "\ncurdle: interrupted; nothing was written\n");
    ::_exit(128 + received);
  }).detach();
}

}  // namespace curdle::cli
