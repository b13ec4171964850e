// Fuzz target: the client's WebSocket frames (server/websocket.h). Input: the first byte sets
// how the rest is cut into pieces as a socket might deliver them; the rest is the bytes. Every
// message read must be within the size allowed, every failure must carry a close code, and
// reading must end.
#include <cstddef>
#include <cstdint>
#include <string>

#include "server/websocket.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0 || size > 1 << 20) return 0;
  const size_t piece = 1 + data[0];
  const char* bytes = reinterpret_cast<const char*>(data + 1);
  const size_t n = size - 1;
  constexpr size_t kMaxMessage = 4096;
  curdle::server::WsReader reader(kMaxMessage);
  for (size_t at = 0; at < n; at += piece) {
    reader.feed(bytes + at, std::min(piece, n - at));
    for (;;) {
      const auto next = reader.next();
      if (next.failure) {
        if (next.failure->code < 1000 || next.failure->reason.empty()) __builtin_trap();
        return 0;
      }
      if (!next.message) break;
      if (next.message->payload.size() > kMaxMessage) __builtin_trap();
    }
  }
  return 0;
}
