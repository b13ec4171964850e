// The page's field over one open WebSocket (GET /api/field-socket): each text message is the
// query /api/field takes ("seed=3&set=..."), each answer the same CRD1 bytes as one binary
// message, or its JSON error as a text message; answers come in the order asked. Saves the
// page a fetch's cost on every change (websocket.h).
#pragma once

#include <chrono>
#include <functional>
#include <string>

#include "server/api.h"

namespace curdle::server {

struct FieldSocketLimits {
  size_t max_message = 64 * 1024;             // a query, as a request's address is bounded
  std::chrono::milliseconds idle{300000};     // closed after this long with no message
  std::chrono::milliseconds arrival{10000};   // a message, from its first byte
  std::chrono::milliseconds sending{120000};  // an answer
  // Idle at least this long, a socket gives its place up to a page that waits for one.
  std::chrono::milliseconds yield_after{5000};
};

// Sends the handshake's 101 with `accept` (websocket_accept), then answers the messages on
// `socket`, the first of them starting with `early_bytes` (read with the request), until the
// client closes, a limit is passed, a frame breaks the protocol (closed with its code and
// reason), or `stopping` says so. `answer` makes the reply to one query. `yield`, asked while
// the socket waits idle, closes it (1000) when another page needs its place.
void serve_field_socket(int socket, const std::string& early_bytes, const std::string& accept,
                        const FieldSocketLimits& limits,
                        const std::function<ApiResponse(const std::string& query)>& answer,
                        const std::function<bool()>& stopping,
                        const std::function<bool()>& yield = {});

}  // namespace curdle::server
