#include "lituya/common/stop_request.hpp"

#include <atomic>
#include <csignal>
#include <ctime>

namespace lituya {

namespace {

// Lock-free, so the handler may touch it (a signal handler may use nothing that locks).
std::atomic<int> g_stop_signal{0};
std::atomic<long long> g_first_signal_ns{0};  // CLOCK_MONOTONIC of the first request
static_assert(std::atomic<int>::is_always_lock_free);
static_assert(std::atomic<long long>::is_always_lock_free);

struct sigaction g_previous_int, g_previous_term;

// clock_gettime is async-signal-safe (POSIX.1-2008).
long long monotonic_ns() {
  timespec now{};
  clock_gettime(CLOCK_MONOTONIC, &now);
  return static_cast<long long>(now.tv_sec) * 1000000000LL + now.tv_nsec;
}

// One request often arrives twice within microseconds: `timeout` and some job schedulers
// signal the process and then its process group. Only a signal this long after the first
// counts as a second request.
constexpr long long kRepeatNs = 1000000000LL;

extern "C" void on_stop_signal(int signal) {
  const long long now = monotonic_ns();
  int expected = 0;
  if (g_stop_signal.compare_exchange_strong(expected, signal)) {
    g_first_signal_ns.store(now);
    return;
  }
  if (now - g_first_signal_ns.load() < kRepeatNs) return;
  // A second request: the user wants out now. Give the signal its default action (end the
  // process) and deliver it again; both calls are async-signal-safe.
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

StopSignalScope::StopSignalScope() {
  g_stop_signal.store(0);
  struct sigaction action {};
  action.sa_handler = on_stop_signal;
  sigemptyset(&action.sa_mask);
  // SA_RESTART: a write interrupted by the signal goes on instead of failing with EINTR, so
  // the last state can still be written.
  action.sa_flags = SA_RESTART;
  sigaction(SIGINT, &action, &g_previous_int);
  sigaction(SIGTERM, &action, &g_previous_term);
}

StopSignalScope::~StopSignalScope() {
  sigaction(SIGINT, &g_previous_int, nullptr);
  sigaction(SIGTERM, &g_previous_term, nullptr);
}

int stop_signal() {
  return g_stop_signal.load(std::memory_order_relaxed);
}

void set_stop_signal(int signal) {
  g_stop_signal.store(signal);
}

std::string signal_name(int signal) {
  if (signal == SIGINT) return "SIGINT";
  if (signal == SIGTERM) return "SIGTERM";
  return "signal " + std::to_string(signal);
}

}  // namespace lituya
