// Waiting on a connection's socket with a deadline, for the HTTP connections and the field
// socket alike: poll(2) retried across signals, and long waits taken in short steps so that a
// stopping server is seen.
#pragma once

#include <chrono>
#include <functional>

namespace curdle::server {

// Waits until `socket` can be read (events POLLIN) or written (POLLOUT), at most `wait`; true
// also when the connection hung up or failed (the next read or write says which), false on
// timeout or error.
bool wait_for(int socket, short events, std::chrono::milliseconds wait);

// Waits until `socket` can be read, at most until `until`, in steps of 100 ms while
// `keep_waiting` holds; false when the time is up or it no longer holds.
bool readable_before(int socket, std::chrono::steady_clock::time_point until,
                     const std::function<bool()>& keep_waiting);

}  // namespace curdle::server
