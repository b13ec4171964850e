#include "server/field_socket.h"

#include <poll.h>
#include <sys/socket.h>

#include <cerrno>

#include "server/socket_wait.h"
#include "server/websocket.h"

namespace curdle::server {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

// The server's side of one socket: reads that wait at most until a deadline, whole frames sent.
class SocketSide {
 public:
  SocketSide(int socket, const FieldSocketLimits& limits) : socket_(socket), limits_(limits) {}

  // Waits until bytes come, in steps so that a stopping server is seen; false when the time is
  // up, the server stops or the connection fails.
  bool wait_readable(Clock::time_point until, const std::function<bool()>& stopping) const {
    return readable_before(socket_, until, [&] { return !stopping(); });
  }

  // The bytes that have come, at most a buffer's worth; 0 when the client closed.
  ssize_t receive(char* buffer, size_t size) const { return ::recv(socket_, buffer, size, 0); }

  // One whole frame, within the time an answer may take.
  bool send_frame(WsOpcode opcode, const std::string& payload) const {
    const std::string header = websocket_frame_header(opcode, payload.size());
    const auto until = Clock::now() + limits_.sending;
    return send_all(header, until) && send_all(payload, until);
  }

  bool send_handshake(const std::string& accept) const {
    return send_all(
        "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\n"
        "Connection: Upgrade\r\nSec-WebSocket-Accept: " +
            accept + "\r\n\r\n",
        Clock::now() + limits_.sending);
  }

  // Sends the close frame, then reads what the client still sends until it closes too (at most
  // a second): a socket closed with bytes unread is reset, and the reset can reach the client
  // before the close frame it would have read.
  void close(uint16_t code, const std::string& reason) const {
    send_frame(WsOpcode::close, websocket_close_payload(code, reason));
    ::shutdown(socket_, SHUT_WR);
    const auto until = Clock::now() + milliseconds(1000);
    char sink[4096];
    while (wait_readable(until, [] { return false; }) && receive(sink, sizeof sink) > 0) {
    }
  }

 private:
  bool send_all(const std::string& bytes, Clock::time_point until) const {
    for (size_t at = 0; at < bytes.size();) {
      const auto left = std::chrono::duration_cast<milliseconds>(until - Clock::now());
      if (left.count() <= 0 || !wait_for(socket_, POLLOUT, left)) return false;
      const ssize_t n = ::send(socket_, bytes.data() + at, bytes.size() - at, MSG_NOSIGNAL);
      if (n < 0 && errno != EINTR && errno != EAGAIN) return false;
      if (n > 0) at += static_cast<size_t>(n);
    }
    return true;
  }

  int socket_;
  const FieldSocketLimits& limits_;
};

// The answer to one query: CRD1 bytes as binary, an error's JSON as text.
bool send_answer(const SocketSide& side, const ApiResponse& r) {
  if (r.status == 200 && r.content_type != kJsonType)
    return side.send_frame(WsOpcode::binary, r.body);
  return side.send_frame(WsOpcode::text, r.body);
}

}  // namespace

void serve_field_socket(int socket, const std::string& early_bytes, const std::string& accept,
                        const FieldSocketLimits& limits,
                        const std::function<ApiResponse(const std::string&)>& answer,
                        const std::function<bool()>& stopping, const std::function<bool()>& yield) {
  const SocketSide side(socket, limits);
  if (!side.send_handshake(accept)) return;
  WsReader reader(limits.max_message);
  reader.feed(early_bytes.data(), early_bytes.size());
  char buffer[16384];
  for (;;) {
    // Idle, a connection waits for a message's first byte; a message once begun must arrive
    // within `arrival`, however slowly it trickles.
    bool begun = reader.has_partial();
    auto until = Clock::now() + (begun ? limits.arrival : limits.idle);
    WsReader::Next next;
    // Idle, it may be asked to give its place to a page that waits.
    const auto unwanted = [&] { return stopping() || (!begun && yield && yield()); };
    while (!(next = reader.next()).message && !next.failure) {
      if (!side.wait_readable(until, unwanted)) {
        if (stopping())
          side.close(1001, "the server is stopping");
        else if (!begun && yield && yield())
          side.close(1000, "idle while another page waits for a socket");
        else if (begun)
          side.close(1008, "a message must arrive whole within its time");
        else
          side.close(1000, "idle");
        return;
      }
      const ssize_t n = side.receive(buffer, sizeof buffer);
      if (n <= 0) return;  // closed, or failed
      reader.feed(buffer, static_cast<size_t>(n));
      if (!begun) begun = true, until = Clock::now() + limits.arrival;
    }
    if (next.failure) {
      side.close(next.failure->code, next.failure->reason);
      return;
    }
    WsMessage& message = *next.message;
    switch (message.opcode) {
      case WsOpcode::close:
        // Its code echoed, as the protocol asks (none when it gave none).
        side.send_frame(WsOpcode::close,
                        message.payload.size() >= 2 ? message.payload.substr(0, 2) : "");
        return;
      case WsOpcode::ping:
        if (!side.send_frame(WsOpcode::pong, message.payload)) return;
        break;
      case WsOpcode::pong:
        break;
      case WsOpcode::binary:
        side.close(1003, "a query is sent as text");
        return;
      default:
        if (!send_answer(side, answer(message.payload))) return;
    }
  }
}

}  // namespace curdle::server
