#pragma once
// The progress of a whole sweep on one line:
//   sweep [########............] 2/5 runs  friction_angle=18  elapsed 1m20s  eta 2m00s
// With runs side by side (--jobs) the line names every run that is going, separated by " | ".
// On a terminal the line is redrawn in place (\r) and each finished run leaves one line above
// it; elsewhere (a log file, CI) the line is printed when a run starts and at the end. The
// solver's own progress is not shown: it goes to a TickStream, which only lets the line
// refresh its clock while a run is going.
#include <chrono>
#include <functional>
#include <ostream>
#include <streambuf>
#include <string>
#include <vector>

namespace lituya::sweep {

// "7.4s", "42s", "1m20s", "2h05m".
std::string format_duration(double seconds);

// "[########............]": `done` of `total` filled, `width` characters inside.
std::string progress_bar(int done, int total, int width = 20);

// A number for a printed table: four significant digits, "-" for NaN or infinity.
std::string short_number(double v);

// Rows of cells as lines of left-aligned columns two spaces apart (the last column unpadded),
// each line ending in a newline: the sweep's printed tables.
std::string align_columns(const std::vector<std::vector<std::string>>& rows);

class SweepProgress {
 public:
  // `out` may be nullptr (no output). `terminal`: redraw the line in place. `jobs`: how many
  // runs go side by side (for the time estimate).
  SweepProgress(std::ostream* out, bool terminal, int total, int jobs = 1);

  // A run starts; `label` says which, e.g. "friction_angle=18" (unique among the runs going).
  void start_run(const std::string& label);
  // Called while a run goes on: redraws the line on a terminal, at most once a second.
  void tick();
  // The run `label` ended after `wall_time` s; `result` is printed on a line of its own.
  // `timed`: the run counts towards the time estimate (false for a run skipped at once).
  void end_run(const std::string& label, const std::string& result, double wall_time, bool timed);
  // The sweep ended: the last state of the line, and a newline on a terminal.
  void finish();

  // The current line, without \r (for tests).
  std::string line() const;

 private:
  using Clock = std::chrono::steady_clock;
  double since(Clock::time_point t) const;
  void draw();

  std::ostream* out_;
  bool terminal_;
  int total_, jobs_, done_ = 0;
  struct Running {
    std::string label;
    Clock::time_point start;
  };
  std::vector<Running> running_;
  Clock::time_point start_, last_draw_;
  double timed_seconds_ = 0;
  int timed_runs_ = 0;
  size_t drawn_ = 0;  // length of the line on screen (terminal)
};

// An ostream that throws its text away and calls `on_write` whenever something is written:
// the solver's progress stream, turned into ticks of the sweep's line.
class TickStream : public std::ostream {
 public:
  explicit TickStream(std::function<void()> on_write);

 private:
  class Buffer : public std::streambuf {
   public:
    explicit Buffer(std::function<void()> on_write) : on_write_(std::move(on_write)) {}

   protected:
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char*, std::streamsize n) override;

   private:
    std::function<void()> on_write_;
  };
  Buffer buffer_;
};

}  // namespace lituya::sweep
