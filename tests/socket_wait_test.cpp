// Waiting on a socket: data and a hung-up peer end the wait, nothing does not; a long wait
// stops as soon as it is no longer wanted.
#include "server/socket_wait.h"

#include <gtest/gtest.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <thread>

namespace curdle::server {
namespace {

using namespace std::chrono_literals;
using Clock = std::chrono::steady_clock;

struct SocketPair {
  SocketPair() { EXPECT_EQ(::socketpair(AF_UNIX, SOCK_STREAM, 0, ends), 0); }
  ~SocketPair() {
    for (const int fd : ends)
      if (fd >= 0) ::close(fd);
  }
  int ends[2] = {-1, -1};
};

TEST(SocketWait, DataOrAHangUpEndsTheWaitAndNothingDoesNot) {
  SocketPair pair;
  const auto start = Clock::now();
  EXPECT_FALSE(wait_for(pair.ends[0], POLLIN, 50ms));
  EXPECT_GE(Clock::now() - start, 45ms);  // poll(2) counts whole milliseconds
  EXPECT_TRUE(wait_for(pair.ends[0], POLLOUT, 50ms));
  ASSERT_EQ(::send(pair.ends[1], "x", 1, 0), 1);
  EXPECT_TRUE(wait_for(pair.ends[0], POLLIN, 5s));
  char byte;
  ASSERT_EQ(::recv(pair.ends[0], &byte, 1, 0), 1);
  ::close(pair.ends[1]);
  pair.ends[1] = -1;
  EXPECT_TRUE(wait_for(pair.ends[0], POLLIN, 5s));  // the peer hung up: a read returns 0
}

TEST(SocketWait, AWaitInStepsEndsAtItsDeadlineOrWhenNoLongerWanted) {
  SocketPair pair;
  auto start = Clock::now();
  EXPECT_FALSE(readable_before(pair.ends[0], start + 250ms, [] { return true; }));
  EXPECT_GE(Clock::now() - start, 240ms);
  // Unwanted after 150 ms, a wait of a minute ends within a step of it.
  std::atomic<bool> wanted{true};
  std::thread stop([&] {
    std::this_thread::sleep_for(150ms);
    wanted = false;
  });
  start = Clock::now();
  EXPECT_FALSE(readable_before(pair.ends[0], start + 60s, [&] { return wanted.load(); }));
  EXPECT_LT(Clock::now() - start, 10s);
  stop.join();
  ASSERT_EQ(::send(pair.ends[1], "x", 1, 0), 1);
  EXPECT_TRUE(readable_before(pair.ends[0], Clock::now() + 60s, [] { return true; }));
}

}  // namespace
}  // namespace curdle::server
