// Connections read with deadlines: a request that trickles in is cut off at its arrival time
// (each byte well within the per-read wait), connections beyond the cap are turned away at
// once, pipelined requests are each answered, and a client that left is noticed.
#include "server/http_connection.h"

#include <arpa/inet.h>
#include <gtest/gtest.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "socket_support.h"

namespace curdle::server {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

class Running {
 public:
  explicit Running(const ConnectionLimits& limits) : http(limits) {
    http.new_task_queue = [] { return new httplib::ThreadPool(16); };
    http.Get("/hello", [](const httplib::Request&, httplib::Response& res) {
      res.set_content("hi", "text/plain");
    });
    port = http.bind_to_any_port("127.0.0.1");
    thread = std::thread([this] { http.listen_after_bind(); });
  }
  ~Running() {
    http.stop();
    thread.join();
  }
  int connect() const {
    const int fd = test::connect_loopback(port);
    EXPECT_GE(fd, 0);
    timeval wait{10, 0};
    ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &wait, sizeof wait);
    return fd;
  }
  std::string request_line() const {
    return "GET /hello HTTP/1.1\r\nHost: 127.0.0.1:" + std::to_string(port) + "\r\n";
  }

  HttpServer http;
  int port = 0;
  std::thread thread;
};

std::string read_all(int fd) {
  std::string answer;
  char buffer[4096];
  for (ssize_t n; (n = ::recv(fd, buffer, sizeof buffer, 0)) > 0;)
    answer.append(buffer, static_cast<size_t>(n));
  return answer;
}

ConnectionLimits quick() {
  ConnectionLimits limits;
  limits.arrival = 600ms;
  limits.keep_alive = 300ms;
  limits.max_connections = 4;
  return limits;
}

TEST(HttpConnection, ARequestThatTricklesInIsCutOffAtItsArrivalTime) {
  Running server(quick());
  const int fd = server.connect();
  const std::string start = server.request_line() + "X-Pad: ";
  ASSERT_EQ(::send(fd, start.data(), start.size(), 0), static_cast<ssize_t>(start.size()));
  // One byte every 50 ms, each far within the 2 s a read may wait, for up to 5 s.
  const auto began = Clock::now();
  bool cut = false;
  while (Clock::now() - began < 5s) {
    if (::send(fd, "a", 1, MSG_NOSIGNAL) != 1) {
      cut = true;
      break;
    }
    char byte;
    if (::recv(fd, &byte, 1, MSG_DONTWAIT) >= 0) {  // an answer (400) or the end
      cut = true;
      break;
    }
    std::this_thread::sleep_for(50ms);
  }
  ::close(fd);
  EXPECT_TRUE(cut) << "still reading a request after 5 s, with an arrival time of 0.6 s";
}

TEST(HttpConnection, ConnectionsBeyondTheCapAreTurnedAwayAndTheRestServed) {
  Running server(quick());
  // Four connections that hold their slot with an unfinished request.
  std::vector<int> held;
  for (int i = 0; i < 4; ++i) {
    held.push_back(server.connect());
    ::send(held.back(), "GET", 3, 0);
  }
  std::this_thread::sleep_for(100ms);
  const int fifth = server.connect();
  const std::string answer = read_all(fifth);
  ::close(fifth);
  EXPECT_EQ(answer.rfind("HTTP/1.1 503", 0), 0u) << answer;
  for (int fd : held) ::close(fd);
  // Once those are cut off, a request is served again.
  std::this_thread::sleep_for(800ms);
  httplib::Client client("127.0.0.1", server.port);
  auto r = client.Get("/hello");
  ASSERT_TRUE(r);
  EXPECT_EQ(r->status, 200);
  EXPECT_EQ(r->body, "hi");
}

TEST(HttpConnection, PipelinedRequestsAreEachAnswered) {
  Running server(quick());
  const int fd = server.connect();
  const std::string two =
      server.request_line() + "\r\n" + server.request_line() + "Connection: close\r\n\r\n";
  ASSERT_EQ(::send(fd, two.data(), two.size(), 0), static_cast<ssize_t>(two.size()));
  const std::string answer = read_all(fd);
  ::close(fd);
  size_t answers = 0;
  for (size_t at = answer.find("HTTP/1.1 200"); at != std::string::npos;
       at = answer.find("HTTP/1.1 200", at + 1))
    ++answers;
  EXPECT_EQ(answers, 2u) << answer;
}

TEST(HttpConnection, AClientThatLeftIsNoticedWithoutReadingItsBytes) {
  int pair[2];
  ASSERT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, pair), 0);
  EXPECT_FALSE(client_gone(pair[0]));
  ::send(pair[1], "x", 1, 0);
  EXPECT_FALSE(client_gone(pair[0]));  // a byte waiting is a client still there
  char byte;
  ::recv(pair[0], &byte, 1, 0);
  ::close(pair[1]);
  EXPECT_TRUE(client_gone(pair[0]));
  ::close(pair[0]);
  EXPECT_FALSE(client_gone(-1));
}

}  // namespace
}  // namespace curdle::server
