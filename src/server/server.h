// `curdle serve`: the page's files and the JSON API (api.h) over HTTP on one address.
// Heavy requests run at most `workers` at a time; the rest wait their turn. A generate of a
// field as small as the page's has a slot of its own, so the page answers while exports run.
#pragma once

#include <atomic>
#include <filesystem>
#include <memory>
#include <string>

#include "server/api.h"
#include "server/field_socket.h"

namespace curdle::server {

// Sent with every answer: the page's own scripts only (the import map in web/index.html by its
// SHA-256; the page test fails when they differ), its own data, and no framing by other sites.
inline constexpr const char* kContentSecurityPolicy =
    "default-src 'self'; script-src 'self' 'sha256-ZpiHiQ0/hV8rYv/RyV4/ZywymYW3ulNwLg6uMorfIq8='; "
    "style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:; connect-src 'self'; "
    "worker-src 'self' blob:; object-src 'none'; base-uri 'none'; form-action 'self'; "
    "frame-ancestors 'none'";

struct ServerConfig {
  ApiContext api;
  std::filesystem::path web_root;     // index.html, its modules, style.css, vendor/three
  int workers = 2;                    // generate, export and search requests at once
  size_t max_body_bytes = 64 * 1024;  // any request's body but a picture's or a query's
  // A query sent by POST as a form body (the page's, once its address would be too long: an
  // outline of 10,000 vertices is about 400 KB).
  size_t max_query_bytes = 4 * 1024 * 1024;
  // A heavy request that runs longer is stopped and answered 503; so is one whose client
  // has gone away.
  double request_seconds = 60;
  // Time a request's line, headers and body may take to arrive, whole (not per read).
  double arrival_seconds = 10;
  // Connections served at once; more are answered 503 at once and closed.
  int max_connections = 96;
  // The page's field socket: its message size and deadlines.
  FieldSocketLimits field_socket;
};

class Server {
 public:
  explicit Server(ServerConfig config);
  ~Server();

  // Binds to host:port (port 0: any free port) and returns the port; throws InputError when
  // the address cannot be used.
  int bind(const std::string& host, int port);
  // Serves until stop(); returns false when it failed to serve.
  bool listen();
  // Safe from any thread; in-flight searches end early.
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The query of a request target ("/api/generate?a=1&b=c=d"), percent-decoded; a value keeps
// every '=' after the first, so targets such as target=ratio:dark=0.1 need no escaping.
Params query_params(const std::string& target);
// The query of a request: its address's, and for a POST its body's as well (the same
// key=value&... text, sent as text/plain).
Params request_params(const std::string& target, const std::string& method,
                      const std::string& body);

// Where the page's files are: beside the program (build tree) or in ../share (installed).
std::filesystem::path find_web_root(const std::filesystem::path& executable);

}  // namespace curdle::server
