// The server's connections, read with deadlines. cpp-httplib 0.11 times out each read on its
// own, so a client that sends one byte a second keeps a thread for good; here a request's
// line, headers and body must all arrive within `arrival`, a response must be taken within
// `sending`, and beyond `max_connections` at once a new connection is answered 503 and closed.
#pragma once

#include <httplib.h>

#include <atomic>
#include <chrono>
#include <string>

namespace curdle::server {

struct ConnectionLimits {
  std::chrono::milliseconds read{2000};        // one read waits at most this
  std::chrono::milliseconds write{10000};      // one write
  std::chrono::milliseconds keep_alive{2000};  // an idle connection closes after this
  std::chrono::milliseconds arrival{10000};    // a whole request, from its first byte
  std::chrono::milliseconds sending{120000};   // a whole response
  int max_connections = 96;
  int requests_per_connection = 100;
};

class HttpServer : public httplib::Server {
 public:
  explicit HttpServer(const ConnectionLimits& limits) : limits_(limits) {}

  // The socket of the request this thread is serving (-1 outside one), so that long work can
  // notice that its client has gone.
  static int current_socket();
  // Ends the connection after the response now being made: a request that could not be framed
  // exactly (a bad line, a body left unread) leaves bytes that must never be read as the next.
  static void close_after_this_request();
  // Hands the connection of the request now being served to its handler for good (a WebSocket
  // after its handshake): whatever httplib writes after the handler is dropped, and the
  // connection closes when the handler returns. Its socket, and the bytes already read past
  // the request (a client that did not wait for the answer).
  struct TakenConnection {
    int socket = -1;
    std::string early_bytes;
  };
  static TakenConnection take_connection();

 private:
  bool process_and_close_socket(socket_t sock) override;
  void serve(socket_t sock);

  ConnectionLimits limits_;
  std::atomic<int> open_{0};
};

// Whether the peer of `socket` has closed or reset its connection (without reading from it).
bool client_gone(int socket);

}  // namespace curdle::server
