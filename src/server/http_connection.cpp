#include "server/http_connection.h"

#include <arpa/inet.h>
#include <netdb.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <string>

#include "server/socket_wait.h"

namespace curdle::server {
namespace {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

thread_local int serving_socket = -1;
thread_local bool closing_after_request = false;
thread_local bool connection_taken = false;
class DeadlineStream;
thread_local DeadlineStream* serving_stream = nullptr;

void address_of(int socket, bool peer, std::string& ip, int& port) {
  sockaddr_storage address{};
  socklen_t length = sizeof address;
  const int got = peer ? ::getpeername(socket, reinterpret_cast<sockaddr*>(&address), &length)
                       : ::getsockname(socket, reinterpret_cast<sockaddr*>(&address), &length);
  char host[NI_MAXHOST] = "", service[NI_MAXSERV] = "";
  if (got != 0 || ::getnameinfo(reinterpret_cast<sockaddr*>(&address), length, host, sizeof host,
                                service, sizeof service, NI_NUMERICHOST | NI_NUMERICSERV) != 0)
    return;
  ip = host;
  port = std::atoi(service);
}

// A connection's bytes, buffered (httplib reads a request line one byte at a time). Reads
// stop at the request's deadline, writes at the response's.
class DeadlineStream : public httplib::Stream {
 public:
  DeadlineStream(int socket, const ConnectionLimits& limits) : socket_(socket), limits_(limits) {}

  // A new request begins: its bytes must all arrive within the arrival time from now.
  void begin_request() {
    arrive_by_ = Clock::now() + limits_.arrival;
    sending_ = false;
  }
  bool has_buffered() const { return begin_ < end_; }
  // The bytes read but not yet taken, given up.
  std::string take_buffered() {
    std::string bytes(buffer_ + begin_, buffer_ + end_);
    begin_ = end_ = 0;
    return bytes;
  }
  // A read ran out of time: the connection is not worth keeping.
  bool failed() const { return failed_; }

  bool is_readable() const override {
    return has_buffered() || wait_for(socket_, POLLIN, read_wait());
  }
  bool is_writable() const override { return wait_for(socket_, POLLOUT, write_wait()); }

  ssize_t read(char* ptr, size_t size) override {
    if (!has_buffered()) {
      // Past the deadline nothing more is read, however steadily it trickles in.
      if (Clock::now() >= arrive_by_ || !wait_for(socket_, POLLIN, read_wait())) {
        failed_ = true;
        return -1;
      }
      const ssize_t n = ::recv(socket_, buffer_, sizeof buffer_, 0);
      if (n <= 0) return n;
      begin_ = 0, end_ = static_cast<size_t>(n);
    }
    const size_t n = std::min(size, end_ - begin_);
    std::copy_n(buffer_ + begin_, n, ptr);
    begin_ += n;
    return static_cast<ssize_t>(n);
  }

  ssize_t write(const char* ptr, size_t size) override {
    if (connection_taken) return static_cast<ssize_t>(size);  // its handler spoke for it
    if (!sending_) send_by_ = Clock::now() + limits_.sending, sending_ = true;
    if (!wait_for(socket_, POLLOUT, write_wait())) return -1;
    return ::send(socket_, ptr, size, MSG_NOSIGNAL);
  }

  void get_remote_ip_and_port(std::string& ip, int& port) const override {
    address_of(socket_, true, ip, port);
  }
  void get_local_ip_and_port(std::string& ip, int& port) const override {
    address_of(socket_, false, ip, port);
  }
  socket_t socket() const override { return socket_; }

 private:
  milliseconds read_wait() const {
    return std::clamp(std::chrono::duration_cast<milliseconds>(arrive_by_ - Clock::now()),
                      milliseconds(0), limits_.read);
  }
  milliseconds write_wait() const {
    return std::clamp(std::chrono::duration_cast<milliseconds>(send_by_ - Clock::now()),
                      milliseconds(0), limits_.write);
  }

  int socket_;
  const ConnectionLimits& limits_;
  Clock::time_point arrive_by_ = Clock::now(), send_by_ = Clock::now();
  bool sending_ = false, failed_ = false;
  char buffer_[4096];
  size_t begin_ = 0, end_ = 0;
};

// Waits for a connection's next request, in short steps so that a stopping server is seen.
bool next_request_arrives(int socket, const std::atomic<socket_t>& listening, milliseconds wait) {
  return readable_before(socket, Clock::now() + wait, [&] { return listening != INVALID_SOCKET; });
}

}  // namespace

int HttpServer::current_socket() { return serving_socket; }

void HttpServer::close_after_this_request() { closing_after_request = true; }

HttpServer::TakenConnection HttpServer::take_connection() {
  connection_taken = true;
  return {serving_socket, serving_stream ? serving_stream->take_buffered() : std::string()};
}

bool client_gone(int socket) {
  if (socket < 0) return false;
  char byte;
  const ssize_t n = ::recv(socket, &byte, 1, MSG_PEEK | MSG_DONTWAIT);
  return n == 0 || (n < 0 && errno != EAGAIN && errno != EWOULDBLOCK && errno != EINTR);
}

bool HttpServer::process_and_close_socket(socket_t sock) {
  if (open_.fetch_add(1) < limits_.max_connections) {
    serve(sock);
  } else {
    static const std::string body = "the server has too many connections; try again\n";
    static const std::string busy =
        "HTTP/1.1 503 Service Unavailable\r\nContent-Type: text/plain\r\nConnection: close\r\n"
        "Content-Length: " +
        std::to_string(body.size()) + "\r\n\r\n" + body;
    ::send(sock, busy.data(), busy.size(), MSG_NOSIGNAL | MSG_DONTWAIT);
  }
  open_.fetch_sub(1);
  ::shutdown(sock, SHUT_RDWR);
  ::close(sock);
  return true;
}

void HttpServer::serve(socket_t sock) {
  serving_socket = sock;
  DeadlineStream stream(sock, limits_);
  serving_stream = &stream;
  for (int left = limits_.requests_per_connection; left > 0; --left) {
    // A new connection's first request may take as long to start as any request may take to
    // arrive: with the keep-alive's 2 s, a client slowed by a busy machine was closed unanswered
    // (ServerTest.MeasureTakesAPicture... failed with an empty reason).
    const milliseconds wait =
        left == limits_.requests_per_connection ? limits_.arrival : limits_.keep_alive;
    if (!stream.has_buffered() && !next_request_arrives(sock, svr_sock_, wait)) break;
    stream.begin_request();
    closing_after_request = false;
    bool closed = false;
    if (!process_request(stream, left == 1, closed, nullptr) || closed || stream.failed() ||
        closing_after_request || connection_taken)
      break;
  }
  serving_socket = -1;
  serving_stream = nullptr;
  connection_taken = false;
}

}  // namespace curdle::server
