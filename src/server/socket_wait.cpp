#include "server/socket_wait.h"

#include <poll.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>

namespace curdle::server {

using Clock = std::chrono::steady_clock;
using std::chrono::milliseconds;

bool wait_for(int socket, short events, milliseconds wait) {
  pollfd p{socket, events, 0};
  const auto end = Clock::now() + wait;
  for (;;) {
    const auto left = std::chrono::duration_cast<milliseconds>(end - Clock::now());
    const int n = ::poll(&p, 1, static_cast<int>(std::max<int64_t>(0, left.count())));
    if (n > 0) return (p.revents & (events | POLLHUP | POLLERR)) != 0;
    if (n == 0 || errno != EINTR) return false;
  }
}

bool readable_before(int socket, Clock::time_point until,
                     const std::function<bool()>& keep_waiting) {
  while (keep_waiting()) {
    const auto left = std::chrono::duration_cast<milliseconds>(until - Clock::now());
    if (left.count() <= 0) return false;
    if (wait_for(socket, POLLIN, std::min(left, milliseconds(100)))) return true;
  }
  return false;
}

}  // namespace curdle::server
