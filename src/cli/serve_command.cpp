#include "cli/serve_command.h"

#include <pthread.h>
#include <signal.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include "app/run.h"
#include "curdle/error.h"
#include "server/server.h"

namespace fs = std::filesystem;

namespace curdle::cli {

int run_serve(const ServeOptions& o) {
  const fs::path exe = fs::read_symlink("/proc/self/exe");
  const fs::path web_root = o.web_root.empty() ? server::find_web_root(exe) : fs::path(o.web_root);
  std::string recipe_path = o.recipe_path;
  if (recipe_path.empty()) {
    recipe_path = (web_root / ".." / "patterns" / kDefaultPattern).lexically_normal().string();
    if (!fs::is_regular_file(recipe_path))
      throw InputError("no recipe given, and the default pattern is not installed at " +
                       recipe_path + "; name a recipe: curdle serve patterns/...toml");
  }
  server::ServerConfig config;
  config.web_root = web_root;
  config.workers = o.workers;
  config.request_seconds = o.request_seconds;
  config.api.recipe_path = recipe_path;
  config.api.recipe_text = app::read_recipe_file(recipe_path);
  config.api.limits.max_cells = o.max_cells;
  if (!o.max_memory.empty())
    config.api.limits.max_memory = app::parse_bytes(o.max_memory, "max_memory");
  // The recipe must be good before the page is offered.
  app::RunRequest check;
  check.recipe_path = recipe_path;
  check.recipe_text = config.api.recipe_text;
  app::resolve_run(check);

  // Ctrl-C and SIGTERM are taken by one thread, which stops the server; every other thread
  // (including httplib's and TBB's) inherits the blocked mask.
  // A shell starts background jobs with SIGINT ignored, and an ignored signal never reaches
  // sigwait: restore the defaults first, so that `kill -INT` stops the server there too.
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);

  server::Server server(config);
  const int port = server.bind(o.host, o.port);
  const std::string host = o.host.find(':') != std::string::npos ? "[" + o.host + "]" : o.host;
  std::printf("curdle: serving %s\n  open http://%s:%d/ (Ctrl-C stops)\n", recipe_path.c_str(),
              host.c_str(), port);
  std::fflush(stdout);

  std::atomic<bool> done{false};
  std::thread waiter([&] {
    int received = 0;
    sigwait(&signals, &received);
    if (done) return;
    std::printf("\ncurdle: stopping (%s)\n", received == SIGINT ? "Ctrl-C" : "SIGTERM");
    std::fflush(stdout);
    server.stop();
    // Requests still running (a large export) would hold the stop; the server writes no files,
    // so after a second it ends at once.
    for (int i = 0; i < 100 && !done; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (!done) {
      std::printf("curdle: stopped (requests in progress dropped)\n");
      std::fflush(stdout);
      std::_Exit(0);
    }
  });
  const bool served = server.listen();
  // listen() also returns on failure: wake the waiter so that it can be joined.
  done = true;
  pthread_kill(waiter.native_handle(), SIGTERM);
  waiter.join();
  if (!served) {
    std::fprintf(stderr, "curdle: error: the server stopped unexpectedly\n");
    return 1;
  }
  std::printf("curdle: stopped\n");
  return 0;
}

}  // namespace curdle::cli
