// The project's one way to run a loop on several threads (mu's base points, argtool's batches).
#pragma once

#include <cstddef>
#include <functional>
#include <thread>

namespace arg {

// Runs f(i) once for every i in [0, n), on the calling thread and up to threads - 1 others,
// indices handed out in increasing order. Results must go to per-index slots, so that they do
// not depend on the thread count.
//
// - Threads start with every signal blocked: inside a database server the signal handlers
//   (query cancel, termination) must run on the server's own thread, the calling one.
// - A thread that cannot start (out of memory or of processes) leaves its share to the others
//   and to the calling thread, which always works too; the process never terminates over it.
// - When f throws, indices above the failing one are no longer started; once every thread has
//   joined, the exception of the lowest failing index is rethrown here (the same one whatever
//   the thread count, when f fails the same way each time).
// - On Linux the threads it starts are named kWorkerThreadName (/proc/PID/task/*/comm).
void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& f);

inline constexpr char kWorkerThreadName[] = "arg worker";

// Starts a thread running `body`, or throws (as std::thread's constructor throws
// std::system_error). Tests give parallel_for one that fails.
using ThreadStarter = std::function<std::thread(std::function<void()> body)>;

// The same, starting threads with `start` instead of std::thread's constructor.
void parallel_for(std::size_t n, int threads, const std::function<void(std::size_t)>& f,
                  const ThreadStarter& start);

}  // namespace arg
