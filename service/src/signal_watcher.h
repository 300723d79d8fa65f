// dem_server's signals: SIGINT and SIGTERM are blocked in every thread and
// collected by one thread with sigwait, so a signal is an ordinary event on
// an ordinary thread: it asks the server to shut down gracefully. SIGUSR1
// (sent by stop()) ends the wait.
#pragma once

#include <signal.h>
#include <spdlog/spdlog.h>

#include <thread>

namespace dem::service {

class SignalWatcher {
 public:
  SignalWatcher() {
    sigemptyset(&signals_);
    sigaddset(&signals_, SIGINT);
    sigaddset(&signals_, SIGTERM);
    sigaddset(&signals_, SIGUSR1);
    pthread_sigmask(SIG_BLOCK, &signals_, nullptr);  // before any thread starts: they inherit it
  }
  ~SignalWatcher() { stop(); }
  SignalWatcher(const SignalWatcher&) = delete;
  SignalWatcher& operator=(const SignalWatcher&) = delete;

  template <typename OnSignal>
  void start(OnSignal on_signal) {
    thread_ = std::thread([this, on_signal] {
      for (;;) {
        int signal = 0;
        if (sigwait(&signals_, &signal) != 0 || signal == SIGUSR1) return;
        spdlog::info("received {}: shutting down", signal == SIGINT ? "SIGINT" : "SIGTERM");
        on_signal();
      }
    });
  }
  void stop() {
    if (!thread_.joinable()) return;
    pthread_kill(thread_.native_handle(), SIGUSR1);
    thread_.join();
  }

 private:
  sigset_t signals_;
  std::thread thread_;
};

}  // namespace dem::service
