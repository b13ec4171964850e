// The WebSocket protocol (RFC 6455) as the page's field channel needs it, free of IO: the
// handshake's answer, the client's frames read from bytes as they come, and the server's frames.
// A fetch costs Chromium 6-10 ms on its own on a two-core machine, a message on an open socket
// about 3 ms (measured over loopback, 4 KB answers): the page's redraw is mostly that cost.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace curdle::server {

enum class WsOpcode : uint8_t {
  continuation = 0,
  text = 1,
  binary = 2,
  close = 8,
  ping = 9,
  pong = 10
};

// The Sec-WebSocket-Accept for a client's Sec-WebSocket-Key; nullopt when the key is not the
// base64 of 16 bytes the protocol requires.
std::optional<std::string> websocket_accept(std::string_view key);

// One whole message from the client (unmasked), or the reason the connection must close.
struct WsMessage {
  WsOpcode opcode = WsOpcode::text;
  std::string payload;
};
struct WsFailure {
  uint16_t code;  // the close code sent back (1002 protocol error, 1009 too big, ...)
  std::string reason;
};

// Reads the client's frames from the bytes fed to it, in any pieces. Every client frame must be
// masked; a message may come in fragments, but never more than `max_message` bytes in all, and
// control frames (close, ping, pong) are at most 125 bytes and never fragmented.
class WsReader {
 public:
  explicit WsReader(size_t max_message) : max_message_(max_message) {}

  void feed(const char* data, size_t size) { buffer_.append(data, size); }
  // Part of a message has come, not all of it.
  bool has_partial() const { return !buffer_.empty() || fragmented_.has_value(); }
  // The next whole message, if its bytes have all come; a failure ends the connection.
  struct Next {
    std::optional<WsMessage> message;
    std::optional<WsFailure> failure;
  };
  Next next();

 private:
  size_t max_message_;
  std::string buffer_;
  std::string fragments_;  // a fragmented message's parts so far
  std::optional<WsOpcode> fragmented_;
};

// A frame from the server (never masked, always final): its header, then the payload.
std::string websocket_frame_header(WsOpcode opcode, uint64_t length);
// A close frame's payload: the code, then the reason cut to fit 125 bytes.
std::string websocket_close_payload(uint16_t code, std::string_view reason);

}  // namespace curdle::server
