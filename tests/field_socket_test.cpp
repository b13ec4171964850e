// The page's field over a WebSocket: a server answering over one socket with the very bytes
// /api/field answers, refusing the handshakes and frames it must, and closing sockets left
// idle or trickled into.
#include "server/field_socket.h"

#include <gtest/gtest.h>
#include <httplib.h>
#include <poll.h>

#include <atomic>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <thread>

#include "server/server.h"
#include "server_support.h"
#include "socket_support.h"
#include "websocket_support.h"

namespace curdle::server {
namespace {

using test::client_frame;
using test::encoded;
using test::text_frame;

const std::string kRecipe =
    std::string(CURDLE_SOURCE_DIR) + "/patterns/paper/fig8-segment-of-large-curd.toml";

class FieldSocketTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    serving_ = new test::ServerOnLoopback(test::server_config(kRecipe));
  }
  static void TearDownTestSuite() { delete serving_; }

  // A socket that has sent `headers` after the request line; its answer's head is read into
  // `head` (up to the blank line), what followed it left in `rest`.
  int open(const std::string& headers, std::string& head, std::string& rest) {
    const int fd = test::connect_loopback(port());
    timeval wait{30, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
    const std::string request =
        "GET /api/field-socket HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port()) + "\r\n" +
        headers + "\r\n";
    ::send(fd, request.data(), request.size(), MSG_NOSIGNAL);
    std::string bytes;
    char buffer[4096];
    while (bytes.find("\r\n\r\n") == std::string::npos) {
      const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
      if (n <= 0) break;
      bytes.append(buffer, static_cast<size_t>(n));
    }
    const size_t end = bytes.find("\r\n\r\n");
    head = bytes.substr(0, end);
    rest = end == std::string::npos ? "" : bytes.substr(end + 4);
    return fd;
  }
  static std::string upgrade_headers(const std::string& extra = "") {
    return "Upgrade: websocket\r\nConnection: keep-alive, Upgrade\r\n"
           "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n" +
           extra;
  }

  // The next frame from the server: its first byte and payload ({0, ""} when none came).
  static std::pair<uint8_t, std::string> read_frame(int fd, std::string& rest) {
    auto need = [&](size_t n) {
      char buffer[65536];
      while (rest.size() < n) {
        const ssize_t got = ::recv(fd, buffer, sizeof buffer, 0);
        if (got <= 0) return false;
        rest.append(buffer, static_cast<size_t>(got));
      }
      return true;
    };
    if (!need(2)) return {0, ""};
    const auto first = static_cast<uint8_t>(rest[0]);
    uint64_t length = static_cast<uint8_t>(rest[1]) & 0x7f;
    size_t at = 2;
    if (length >= 126) {
      const size_t bytes = length == 126 ? 2 : 8;
      if (!need(at + bytes)) return {0, ""};
      length = 0;
      for (size_t i = 0; i < bytes; ++i) length = length << 8 | static_cast<uint8_t>(rest[at + i]);
      at += bytes;
    }
    if (!need(at + length)) return {0, ""};
    std::string payload = rest.substr(at, length);
    rest.erase(0, at + length);
    return {first, payload};
  }

  static int port() { return serving_->port(); }

  static test::ServerOnLoopback* serving_;
};
test::ServerOnLoopback* FieldSocketTest::serving_ = nullptr;

// The CRD1 answer without its head's "server_ms", which differs between any two answers.
std::string without_timing(const std::string& crd1) {
  if (crd1.size() < 8 || crd1.compare(0, 4, kFieldMagic) != 0) return "not CRD1: " + crd1;
  uint32_t n = 0;
  for (int i = 3; i >= 0; --i) n = n << 8 | static_cast<uint8_t>(crd1[4 + i]);
  auto head = nlohmann::json::parse(crd1.substr(8, n));
  head.erase("server_ms");
  return head.dump() + crd1.substr(8 + n);
}

TEST_F(FieldSocketTest, EachQueryIsAnsweredWithTheBytesOfApiField) {
  std::string head, rest;
  const int fd = open(
      upgrade_headers("Origin: http://127.0.0.1:" + std::to_string(port()) + "\r\n"), head, rest);
  ASSERT_EQ(head.rfind("HTTP/1.1 101", 0), 0u) << head;
  EXPECT_NE(head.find("Sec-WebSocket-Accept: s3pPLMBiTxaQ9kYGzzhZRbK+xOo="), std::string::npos);
  httplib::Client client("127.0.0.1", port());
  const std::vector<std::string> queries = {
      "seed=3", "seed=4&set=" + encoded("field.cells=[300,200]"),
      "seed=5&set=" + encoded("curds.0.probabilities=[\"1/2\",\"1/2\",\"1/2\"]")};
  // Sent together: answered in order, on the one socket.
  std::string all;
  for (const auto& q : queries) all += text_frame(q);
  ::send(fd, all.data(), all.size(), MSG_NOSIGNAL);
  for (const auto& q : queries) {
    const auto [first, payload] = read_frame(fd, rest);
    EXPECT_EQ(first, 0x82) << q;  // a final binary frame
    auto fetched = client.Get(("/api/field?" + q).c_str());
    ASSERT_TRUE(fetched);
    ASSERT_EQ(fetched->status, 200);
    EXPECT_EQ(without_timing(payload), without_timing(fetched->body)) << q;
  }
  // A bad query is its JSON error, as text; the socket stays open for the next.
  const std::string bad = text_frame("seed=3&set=" + encoded("lattice.base=1")) +
                          text_frame("seed=%FF%FE") + client_frame(0x89, "are you there");
  ::send(fd, bad.data(), bad.size(), MSG_NOSIGNAL);
  auto [first, error] = read_frame(fd, rest);
  EXPECT_EQ(first, 0x81);
  EXPECT_NE(nlohmann::json::parse(error)["error"].get<std::string>().find("base"),
            std::string::npos)
      << error;
  std::tie(first, error) = read_frame(fd, rest);
  EXPECT_NE(error.find("not UTF-8"), std::string::npos) << error;
  EXPECT_EQ(read_frame(fd, rest), std::make_pair(uint8_t{0x8a}, std::string("are you there")));
  // A close is answered with the same code, and the connection ends.
  const std::string close = client_frame(0x88, std::string("\x03\xe8", 2));
  ::send(fd, close.data(), close.size(), MSG_NOSIGNAL);
  EXPECT_EQ(read_frame(fd, rest), std::make_pair(uint8_t{0x88}, std::string("\x03\xe8", 2)));
  EXPECT_EQ(read_frame(fd, rest).first, 0);
  ::close(fd);
}

TEST_F(FieldSocketTest, BadHandshakesAndOtherSitesAreRefused) {
  std::string head, rest;
  auto status_of = [&](const std::string& headers) {
    ::close(open(headers, head, rest));
    return head.substr(0, 12);
  };
  // A plain GET is told what the address is; its body may come after its head.
  const int plain = open("", head, rest);
  EXPECT_EQ(head.substr(0, 12), "HTTP/1.1 426");
  char buffer[4096];
  for (ssize_t n; rest.find("fetch /api/field") == std::string::npos &&
                  (n = ::recv(plain, buffer, sizeof buffer, 0)) > 0;)
    rest.append(buffer, static_cast<size_t>(n));
  EXPECT_NE(rest.find("is a WebSocket"), std::string::npos) << rest;
  ::close(plain);
  EXPECT_EQ(status_of("Upgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\n"
                      "Sec-WebSocket-Key: short==\r\n"),
            "HTTP/1.1 426");
  EXPECT_EQ(status_of("Upgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 8\r\n"
                      "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n"),
            "HTTP/1.1 426");
  EXPECT_EQ(status_of(upgrade_headers("Origin: http://evil.example\r\n")), "HTTP/1.1 403");
  EXPECT_EQ(status_of(upgrade_headers("Sec-Fetch-Site: cross-site\r\n")), "HTTP/1.1 403");
  // An unmasked frame closes the socket with 1002.
  const int fd = open(upgrade_headers(), head, rest);
  ASSERT_EQ(head.rfind("HTTP/1.1 101", 0), 0u) << head;
  const std::string unmasked = client_frame(0x81, "seed=1", false);
  ::send(fd, unmasked.data(), unmasked.size(), MSG_NOSIGNAL);
  const auto [first, payload] = read_frame(fd, rest);
  EXPECT_EQ(first, 0x88);
  EXPECT_EQ(payload.substr(0, 2), std::string("\x03\xea", 2));
  ::close(fd);
  // The server still answers.
  httplib::Client client("127.0.0.1", port());
  auto r = client.Get("/api/field?seed=1");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
}

TEST_F(FieldSocketTest, SocketsPastTheLimitAreTurnedAwayAndTheirThreadsComeBack) {
  std::vector<int> open_sockets;
  std::string head, rest;
  for (int i = 0; i < 8; ++i) {
    open_sockets.push_back(open(upgrade_headers(), head, rest));
    EXPECT_EQ(head.rfind("HTTP/1.1 101", 0), 0u) << i << ": " << head;
  }
  ::close(open(upgrade_headers(), head, rest));
  EXPECT_EQ(head.rfind("HTTP/1.1 503", 0), 0u) << head;
  for (const int fd : open_sockets) ::close(fd);
  // Each closed socket frees its place: within moments a new one opens.
  bool reopened = false;
  for (int tries = 0; tries < 100 && !reopened; ++tries) {
    const int fd = open(upgrade_headers(), head, rest);
    reopened = head.rfind("HTTP/1.1 101", 0) == 0;
    ::close(fd);
    if (!reopened) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  EXPECT_TRUE(reopened);
}

// Eight pages' sockets left idle do not keep a ninth out for their five minutes: the one idle
// longest gives its place up (closed with 1000) and the ninth opens.
TEST(FieldSocketDeadlines, AnIdleSocketGivesItsPlaceToAPageThatWaits) {
  ServerConfig config = test::server_config(kRecipe);
  config.api.recipe_text =
      "[lattice]\nbase = 2\n[[curds]]\nname = \"a\"\nprobabilities = [\"1/2\"]\n";
  config.field_socket.yield_after = std::chrono::milliseconds(200);
  const test::ServerOnLoopback serving(config);
  const int port = serving.port();
  const std::string request =
      "GET /api/field-socket HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
      "\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\n"
      "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n";
  auto open_socket = [&](std::string& head) {
    const int fd = test::connect_loopback(port);
    timeval wait{10, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
    ::send(fd, request.data(), request.size(), MSG_NOSIGNAL);
    char buffer[4096];
    const ssize_t n = ::recv(fd, buffer, sizeof buffer, 0);
    head.assign(buffer, n > 0 ? static_cast<size_t>(n) : 0);
    return fd;
  };
  std::vector<int> held;
  std::string head;
  for (int i = 0; i < 8; ++i) {
    held.push_back(open_socket(head));
    ASSERT_EQ(head.rfind("HTTP/1.1 101", 0), 0u) << i << ": " << head;
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(400));
  const int ninth = open_socket(head);
  EXPECT_EQ(head.rfind("HTTP/1.1 101", 0), 0u) << head;
  // The first, idle longest, was closed with 1000.
  char buffer[4096];
  const ssize_t n = ::recv(held.front(), buffer, sizeof buffer, 0);
  const std::string closing(buffer, n > 0 ? static_cast<size_t>(n) : 0);
  EXPECT_NE(closing.find("\x03\xe8idle while another page waits"), std::string::npos) << closing;
  ::close(ninth);
  for (const int fd : held) ::close(fd);
}

// A socket left idle is closed with 1000, and one whose message trickles in past its arrival
// time with 1008, each after the time the server was given.
TEST(FieldSocketDeadlines, AnIdleOrTricklingSocketIsClosed) {
  ServerConfig config = test::server_config(kRecipe);
  config.api.recipe_text =
      "[lattice]\nbase = 2\n[[curds]]\nname = \"a\"\nprobabilities = [\"1/2\"]\n";
  config.field_socket.idle = std::chrono::milliseconds(300);
  config.field_socket.arrival = std::chrono::milliseconds(300);
  const test::ServerOnLoopback serving(config);
  const int port = serving.port();
  auto open_socket = [&] {
    const int fd = test::connect_loopback(port);
    timeval wait{30, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
    const std::string request =
        "GET /api/field-socket HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) +
        "\r\nUpgrade: websocket\r\nConnection: Upgrade\r\nSec-WebSocket-Version: 13\r\n"
        "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\n\r\n";
    ::send(fd, request.data(), request.size(), MSG_NOSIGNAL);
    return fd;
  };
  // Everything the server sends until it closes: the 101, then the close frame.
  auto until_closed = [](int fd) {
    std::string bytes;
    char buffer[4096];
    for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;)
      bytes.append(buffer, static_cast<size_t>(n));
    return bytes;
  };
  const auto started = std::chrono::steady_clock::now();
  const int idle = open_socket();
  const std::string idle_bytes = until_closed(idle);
  const auto idle_took = std::chrono::steady_clock::now() - started;
  EXPECT_NE(idle_bytes.find("101 Switching"), std::string::npos);
  EXPECT_NE(idle_bytes.find(std::string("\x88\x06\x03\xe8idle", 8)), std::string::npos);
  EXPECT_GE(idle_took, std::chrono::milliseconds(300));
  ::close(idle);
  // A message's first bytes, then one byte every 100 ms: cut off at 300 ms.
  const int trickle = open_socket();
  const std::string frame = text_frame("seed=1&set=" + std::string(40, 'x'));
  std::atomic<bool> closed{false};
  std::thread sender([&] {
    for (size_t i = 0; i < frame.size() && !closed; ++i) {
      if (::send(trickle, frame.data() + i, 1, MSG_NOSIGNAL) != 1) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
  });
  const std::string trickle_bytes = until_closed(trickle);
  closed = true;
  EXPECT_NE(trickle_bytes.find("\x03\xf0"
                               "a message must arrive whole"),
            std::string::npos)
      << trickle_bytes;
  sender.join();
  ::close(trickle);
}

}  // namespace
}  // namespace curdle::server
