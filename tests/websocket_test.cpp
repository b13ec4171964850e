// The WebSocket protocol's pieces the page's field socket uses: the handshake's answer, the
// client's frames however they are cut, every way a frame may break the protocol, and the
// server's frame headers.
#include "server/websocket.h"

#include <gtest/gtest.h>

#include <vector>

#include "websocket_support.h"

namespace curdle::server {
namespace {

using test::client_frame;
using test::text_frame;

TEST(WebSocket, TheHandshakeAnswersAsTheStandardsExampleSays) {
  // RFC 6455, section 1.3.
  EXPECT_EQ(websocket_accept("dGhlIHNhbXBsZSBub25jZQ=="), "s3pPLMBiTxaQ9kYGzzhZRbK+xOo=");
  for (const char* bad : {"", "dGhlIHNhbXBsZSBub25jZQ", "dGhlIHNhbXBsZSBub25jZQ=!",
                          "dGhlIHNhbXBsZSBub25jZ*==", "dGhlIHNhbXBsZSBub25jZQ==="})
    EXPECT_FALSE(websocket_accept(bad)) << bad;
}

TEST(WebSocket, MessagesAreReadHoweverTheirBytesAreCut) {
  const std::string big(70000, 'q');   // a 64-bit length
  const std::string middle(300, 'm');  // a 16-bit length
  const std::string bytes = text_frame("seed=3") + client_frame(0x82, middle) +
                            client_frame(0x01, "par") + client_frame(0x89, "ping!") +
                            client_frame(0x80, "ts") + text_frame(big);
  for (const size_t piece : {size_t{1}, size_t{7}, bytes.size()}) {
    WsReader reader(1 << 20);
    std::vector<WsMessage> got;
    for (size_t at = 0; at < bytes.size(); at += piece) {
      reader.feed(bytes.data() + at, std::min(piece, bytes.size() - at));
      for (auto next = reader.next(); next.message; next = reader.next())
        got.push_back(*next.message);
      EXPECT_FALSE(reader.next().failure);
    }
    ASSERT_EQ(got.size(), 5u) << piece;
    EXPECT_EQ(got[0].payload, "seed=3");
    EXPECT_EQ(got[1].opcode, WsOpcode::binary);
    EXPECT_EQ(got[1].payload, middle);
    // A ping between a message's fragments comes first; the fragments make one message.
    EXPECT_EQ(got[2].opcode, WsOpcode::ping);
    EXPECT_EQ(got[2].payload, "ping!");
    EXPECT_EQ(got[3].opcode, WsOpcode::text);
    EXPECT_EQ(got[3].payload, "parts");
    EXPECT_EQ(got[4].payload, big);
    EXPECT_FALSE(reader.has_partial());
  }
}

TEST(WebSocket, FramesThatBreakTheProtocolEndTheConnectionWithACode) {
  const std::string long_text(200, 'x');
  const struct {
    std::string bytes;
    uint16_t code;
    const char* says;
  } cases[] = {
      {client_frame(0x81, "seed=1", false), 1002, "masked"},
      {client_frame(0xc1, "seed=1"), 1002, "reserved"},
      {client_frame(0x83, "seed=1"), 1002, "opcode"},
      {client_frame(0x09, "ping"), 1002, "control"},
      {client_frame(0x89, long_text), 1002, "control"},
      {client_frame(0x80, "orphan"), 1002, "continuation"},
      {client_frame(0x01, "a") + text_frame("b"), 1002, "before the last one ended"},
      {text_frame(std::string(101, 'x')), 1009, "at most 100 bytes"},
      {client_frame(0x01, std::string(60, 'x')) + client_frame(0x80, std::string(60, 'x')), 1009,
       "at most 100 bytes"},
  };
  for (const auto& c : cases) {
    WsReader reader(100);
    reader.feed(c.bytes.data(), c.bytes.size());
    WsReader::Next next = reader.next();
    while (next.message) next = reader.next();
    ASSERT_TRUE(next.failure) << c.says;
    EXPECT_EQ(next.failure->code, c.code) << c.says;
    EXPECT_NE(next.failure->reason.find(c.says), std::string::npos) << next.failure->reason;
  }
  // A length past any message is refused from its header, before its bytes could be buffered.
  WsReader reader(100);
  const std::string huge = std::string("\x81\xff", 2) + std::string(8, '\x7f');
  reader.feed(huge.data(), huge.size());
  ASSERT_TRUE(reader.next().failure);
}

TEST(WebSocket, ServerFramesCarryTheirLengthAsTheProtocolSays) {
  EXPECT_EQ(websocket_frame_header(WsOpcode::binary, 125), std::string("\x82\x7d", 2));
  EXPECT_EQ(websocket_frame_header(WsOpcode::binary, 126), std::string("\x82\x7e\x00\x7e", 4));
  EXPECT_EQ(websocket_frame_header(WsOpcode::text, 65535), std::string("\x81\x7e\xff\xff", 4));
  EXPECT_EQ(websocket_frame_header(WsOpcode::binary, 65536),
            std::string("\x82\x7f\x00\x00\x00\x00\x00\x01\x00\x00", 10));
  // A close reason is cut to fit 125 bytes between characters, never inside one.
  std::string reason;
  for (int i = 0; i < 70; ++i) reason += "\xc3\xa9";  // é, two bytes each
  const std::string payload = websocket_close_payload(1009, reason);
  EXPECT_EQ(payload.substr(0, 2), std::string("\x03\xf1", 2));
  EXPECT_LE(payload.size(), 125u);
  EXPECT_EQ((payload.size() - 2) % 2, 0u);
}

}  // namespace
}  // namespace curdle::server
