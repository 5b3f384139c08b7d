// Blocking every signal in the calling thread for a scope, so that threads started inside it
// never run the host process's signal handlers.
#pragma once

#include <pthread.h>
#include <signal.h>

namespace arg {

// A thread inherits the signal mask of the thread that starts it. Inside a database server the
// handlers (query cancel, termination, latches) expect to run on the server's own thread, so
// worker threads, and threads that libraries start when loaded, are started with every signal
// blocked; the caller's mask is restored when the scope ends.
class SignalsBlocked {
 public:
  SignalsBlocked() {
    sigset_t all;
    sigfillset(&all);
    pthread_sigmask(SIG_SETMASK, &all, &saved_);
  }
  ~SignalsBlocked() { pthread_sigmask(SIG_SETMASK, &saved_, nullptr); }
  SignalsBlocked(const SignalsBlocked&) = delete;
  SignalsBlocked& operator=(const SignalsBlocked&) = delete;

 private:
  sigset_t saved_;
};

}  // namespace arg
