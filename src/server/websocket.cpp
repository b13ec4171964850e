#include "server/websocket.h"

#include <openssl/evp.h>

#include <algorithm>
#include <array>
#include <cctype>

namespace curdle::server {
namespace {

constexpr std::string_view kHandshakeGuid = "258EAFA5-E914-47DA-95CA-C5AB0DC85B11";

std::string base64(const unsigned char* data, size_t size) {
  std::string out(4 * ((size + 2) / 3), '\0');
  const int n =
      EVP_EncodeBlock(reinterpret_cast<unsigned char*>(out.data()), data, static_cast<int>(size));
  out.resize(static_cast<size_t>(n));
  return out;
}

bool is_base64_of_16_bytes(std::string_view key) {
  if (key.size() != 24 || key.substr(22) != "==") return false;
  for (const char c : key.substr(0, 22))
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/')) return false;
  return true;
}

bool is_control(WsOpcode op) { return static_cast<uint8_t>(op) >= 8; }

bool is_known(uint8_t op) { return op <= 2 || (op >= 8 && op <= 10); }

}  // namespace

std::optional<std::string> websocket_accept(std::string_view key) {
  if (!is_base64_of_16_bytes(key)) return std::nullopt;
  std::string text(key);
  text += kHandshakeGuid;
  // Through EVP: a plain SHA1() may bind to another library's function of that name.
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int size = 0;
  if (EVP_Digest(text.data(), text.size(), digest.data(), &size, EVP_sha1(), nullptr) != 1)
    return std::nullopt;
  return base64(digest.data(), size);
}

WsReader::Next WsReader::next() {
  for (;;) {
    if (buffer_.size() < 2) return {};
    const auto byte = [&](size_t i) { return static_cast<uint8_t>(buffer_[i]); };
    const bool fin = byte(0) & 0x80;
    const uint8_t op = byte(0) & 0x0f;
    if (byte(0) & 0x70) return {{}, WsFailure{1002, "reserved bits set (no extension was agreed)"}};
    if (!is_known(op)) return {{}, WsFailure{1002, "unknown opcode"}};
    if (!(byte(1) & 0x80)) return {{}, WsFailure{1002, "a client's frame must be masked"}};
    const auto opcode = static_cast<WsOpcode>(op);
    uint64_t length = byte(1) & 0x7f;
    size_t at = 2;
    if (length == 126 || length == 127) {
      const size_t bytes = length == 126 ? 2 : 8;
      if (buffer_.size() < at + bytes) return {};
      length = 0;
      for (size_t i = 0; i < bytes; ++i) length = length << 8 | byte(at + i);
      at += bytes;
    }
    if (is_control(opcode) && (!fin || length > 125))
      return {{}, WsFailure{1002, "a control frame is at most 125 bytes and never fragmented"}};
    if (length > max_message_ || fragments_.size() + length > max_message_)
      return {{},
              WsFailure{1009, "a message is at most " + std::to_string(max_message_) + " bytes"}};
    if (buffer_.size() < at + 4 + length) return {};
    const size_t mask_at = at;
    at += 4;
    std::string payload = buffer_.substr(at, static_cast<size_t>(length));
    for (size_t i = 0; i < payload.size(); ++i) payload[i] ^= buffer_[mask_at + i % 4];
    buffer_.erase(0, at + static_cast<size_t>(length));
    if (is_control(opcode)) return {WsMessage{opcode, std::move(payload)}, {}};
    if (opcode == WsOpcode::continuation) {
      if (!fragmented_) return {{}, WsFailure{1002, "a continuation with no message begun"}};
    } else if (fragmented_) {
      return {{}, WsFailure{1002, "a new message before the last one ended"}};
    } else {
      fragmented_ = opcode;
    }
    fragments_ += payload;
    if (!fin) continue;
    WsMessage message{*fragmented_, std::move(fragments_)};
    fragments_.clear();
    fragmented_.reset();
    return {std::move(message), {}};
  }
}

std::string websocket_frame_header(WsOpcode opcode, uint64_t length) {
  std::string header(1, static_cast<char>(0x80 | static_cast<uint8_t>(opcode)));
  if (length < 126) {
    header += static_cast<char>(length);
  } else {
    const size_t bytes = length < 65536 ? 2 : 8;
    header += static_cast<char>(bytes == 2 ? 126 : 127);
    for (size_t i = bytes; i-- > 0;) header += static_cast<char>((length >> (8 * i)) & 0xff);
  }
  return header;
}

std::string websocket_close_payload(uint16_t code, std::string_view reason) {
  std::string payload{static_cast<char>(code >> 8), static_cast<char>(code & 0xff)};
  size_t n = std::min<size_t>(reason.size(), 123);
  // Cut between characters: a close reason must be UTF-8.
  while (n < reason.size() && n > 0 && (static_cast<uint8_t>(reason[n]) & 0xc0) == 0x80) --n;
  payload += reason.substr(0, n);
  return payload;
}

}  // namespace curdle::server
