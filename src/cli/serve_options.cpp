#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "cli/options.h"
#include "cli/serve_command.h"

namespace curdle::cli {

void add_serve_options(CLI::App& c, ServeOptions& o) {
  c.add_option("recipe", o.recipe_path,
               std::string("Recipe file (TOML) (default: the pattern ") + kDefaultPattern +
                   " installed with curdle)");
  c.add_option("--port", o.port, "Port to listen on (default 8080; 0: any free port)")
      ->check(CLI::Range(0, 65535));
  c.add_option("--host", o.host,
               "Address to listen on (default 127.0.0.1, this machine only; give another "
               "explicitly to share the page on a network)")
      ->check(kNotEmpty);
  c.add_option("--web-root", o.web_root, "Directory of the page's files (default: installed)")
      ->check(kNotEmpty);
  c.add_option("--workers", o.workers,
               "Generate, export and search requests run at once (default 2)")
      ->check(CLI::Range(1, 64));
  c.add_option("--request-seconds", o.request_seconds,
               "Longest a generate, export, search or measure may run before it is stopped "
               "and answered 503 (default 60)")
      ->check(CLI::Range(1, 3600));
  c.add_option("--max-cells", o.max_cells,
               "Most cells one request may generate (default 4194304, 2048 x 2048)")
      ->check(CLI::Range(uint64_t{1}, uint64_t{1} << 32));
  c.add_option("--max-memory", o.max_memory,
               "Memory one request may use, e.g. 2G (default: a quarter of physical memory)")
      ->check(kNotEmpty);
}

int exec_serve(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  const fs::path server = exe.parent_path() / "curdle-serve";
  // README command 1 builds `curdle` alone, for the main job: the server is built with the rest.
  if (!fs::is_regular_file(server, ec)) {
    std::fprintf(stderr,
                 "curdle: error: `curdle serve` runs curdle-serve, which is not built beside this "
                 "curdle (%s); build it with `cmake --build --preset release -j2 --target "
                 "curdle_serve` (README command 2 builds it with everything else)\n",
                 server.c_str());
    return 1;
  }
  std::vector<char*> args{const_cast<char*>(server.c_str())};
  for (int i = 2; i < argc; ++i) args.push_back(argv[i]);
  args.push_back(nullptr);
  std::fflush(stdout);
  ::execv(server.c_str(), args.data());
  std::fprintf(stderr, "curdle: internal error: cannot run %s: %s\n", server.c_str(),
               std::strerror(errno));
  return 1;
}

}  // namespace curdle::cli
