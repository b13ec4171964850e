// A server of the test's own on a free loopback port, for the tests of the page's API and its
// field socket: serving from construction until it goes out of scope.
#pragma once

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>

#include "server/server.h"

namespace curdle::test {

// The page's files from the source tree and the recipe at `recipe_path`, read.
inline server::ServerConfig server_config(const std::string& recipe_path) {
  server::ServerConfig config;
  config.web_root = std::filesystem::path(CURDLE_SOURCE_DIR) / "web";
  config.api.recipe_path = recipe_path;
  std::ifstream in(recipe_path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  config.api.recipe_text = text.str();
  return config;
}

class ServerOnLoopback {
 public:
  explicit ServerOnLoopback(const server::ServerConfig& config)
      : server_(config),
        port_(server_.bind("127.0.0.1", 0)),
        thread_([this] { server_.listen(); }) {}
  ~ServerOnLoopback() {
    server_.stop();
    thread_.join();
  }
  ServerOnLoopback(const ServerOnLoopback&) = delete;
  ServerOnLoopback& operator=(const ServerOnLoopback&) = delete;

  int port() const { return port_; }

 private:
  server::Server server_;
  int port_;
  std::thread thread_;
};

}  // namespace curdle::test
