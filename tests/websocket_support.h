// Frames as a client sends them, for the tests of the WebSocket reader and of the server's
// field socket.
#pragma once

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <string>

namespace curdle::test {

// A frame as a client sends it: masked (with a fixed mask, so that tests repeat).
inline std::string client_frame(uint8_t first_byte, const std::string& payload,
                                bool masked = true) {
  std::string frame(1, static_cast<char>(first_byte));
  const uint64_t n = payload.size();
  const char mask_bit = masked ? static_cast<char>(0x80) : 0;
  if (n < 126) {
    frame += static_cast<char>(mask_bit | static_cast<char>(n));
  } else {
    const int bytes = n < 65536 ? 2 : 8;
    frame += static_cast<char>(mask_bit | (bytes == 2 ? 126 : 127));
    for (int i = bytes; i-- > 0;) frame += static_cast<char>((n >> (8 * i)) & 0xff);
  }
  if (!masked) return frame + payload;
  const char mask[4] = {0x37, static_cast<char>(0xfa), 0x21, 0x3d};
  frame.append(mask, 4);
  for (size_t i = 0; i < payload.size(); ++i) frame += static_cast<char>(payload[i] ^ mask[i % 4]);
  return frame;
}
inline std::string text_frame(const std::string& text) { return client_frame(0x81, text); }

// A query value as a URL carries it: every byte but letters and digits as %XX.
inline std::string encoded(const std::string& value) {
  std::string out;
  for (const char c : value) {
    if (std::isalnum(static_cast<unsigned char>(c))) {
      out += c;
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", static_cast<unsigned char>(c));
      out += hex;
    }
  }
  return out;
}

}  // namespace curdle::test
