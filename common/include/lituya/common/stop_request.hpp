#pragma once
// Ctrl-C (SIGINT) and SIGTERM (a job scheduler's time limit, `kill`) ask a long run to stop
// cleanly instead of dying mid-write: the handler only records the signal, and the solve
// checks the record where the state is whole (after a step, at an output), writes that state
// and `completed = false` with the reason, and ends with exit code 128 + the signal number
// (130, 143), as a shell reports a process that a signal ended.
//
// A second signal, a second or more after the first, ends the process at once, as without the
// handler, so a stop that hangs can still be forced. (Sooner, it is the same request delivered
// twice, as `timeout` does: to the process, then to its process group.)
#include <stdexcept>
#include <string>

namespace lituya {

// Installs the handler for SIGINT and SIGTERM for its lifetime and restores the previous
// handlers when it ends. Only `lituya solve` and `lituya run` install it: elsewhere (meshing in
// gmsh, a sweep of many runs) nothing checks the request, and a signal must keep ending the
// process.
class StopSignalScope {
 public:
  StopSignalScope();
  ~StopSignalScope();
  StopSignalScope(const StopSignalScope&) = delete;
  StopSignalScope& operator=(const StopSignalScope&) = delete;
};

// The signal that asked to stop (SIGINT, SIGTERM), or 0. Cheap: one relaxed atomic load, so a
// time loop may ask after every step.
int stop_signal();
inline bool stop_requested() {
  return stop_signal() != 0;
}
// Records a request as the handler does (tests; 0 clears it).
void set_stop_signal(int signal);
// "SIGINT", "SIGTERM", or "signal N".
std::string signal_name(int signal);

// Thrown by the solve where it stops for a signal, after it wrote the last state. `lituya`
// turns it into exit code 128 + signal().
class RunStopped : public std::runtime_error {
 public:
  RunStopped(int signal, const std::string& message)
      : std::runtime_error(message), signal_(signal) {}
  int signal() const { return signal_; }

 private:
  int signal_;
};

}  // namespace lituya
