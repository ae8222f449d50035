#include "lituya/sweep/progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lituya::sweep {

std::string short_number(double v) {
  if (!std::isfinite(v)) return "-";
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

std::string align_columns(const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> width;
  for (const auto& row : rows) {
    if (width.size() < row.size()) width.resize(row.size(), 0);
    for (std::size_t c = 0; c < row.size(); ++c) width[c] = std::max(width[c], row[c].size());
  }
  std::string out;
  for (const auto& row : rows) {
    for (std::size_t c = 0; c < row.size(); ++c) {
      out += row[c];
      if (c + 1 < row.size()) out += std::string(width[c] - row[c].size() + 2, ' ');
    }
    out += "\n";
  }
  return out;
}

std::string format_duration(double seconds) {
  char text[32];
  if (seconds < 9.95) {
    std::snprintf(text, sizeof text, "%.1fs", std::max(0.0, seconds));
    return text;
  }
  const long s = std::lround(seconds);
  if (s < 60)
    std::snprintf(text, sizeof text, "%lds", s);
  else if (s < 3600)
    std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
  return text;
}

std::string progress_bar(int done, int total, int width) {
  const int filled = total > 0 ? std::clamp(done * width / total, 0, width) : width;
  std::string bar(1, '[');
  bar.append(static_cast<size_t>(filled), '#');
  bar.append(static_cast<size_t>(width - filled), '.');
  bar += ']';
  return bar;
}

SweepProgress::SweepProgress(std::ostream* out, bool terminal, int total, int jobs)
    : out_(out),
      terminal_(terminal),
      total_(total),
      jobs_(std::max(1, jobs)),
      start_(Clock::now()) {}

double SweepProgress::since(Clock::time_point t) const {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

std::string SweepProgress::line() const {
  std::string line = "sweep " + progress_bar(done_, total_) + " " + std::to_string(done_) + "/" +
                     std::to_string(total_) + " runs";
  for (size_t r = 0; r < running_.size(); ++r) line += (r == 0 ? "  " : " | ") + running_[r].label;
  line += "  elapsed " + format_duration(since(start_));
  // The mean time of the runs done so far, for the ones going and the rest, shared among the
  // jobs; the time the runs going have had already is taken off.
  if (timed_runs_ > 0 && done_ < total_) {
    const double mean = timed_seconds_ / timed_runs_;
    double current = 0;
    for (const Running& r : running_) current += std::min(since(r.start), mean);
    line += "  eta " + format_duration((mean * (total_ - done_) - current) / jobs_);
  }
  return line;
}

void SweepProgress::draw() {
  if (!out_) return;
  const std::string text = line();
  if (terminal_) {
    // Blanks over what is left of a longer previous line.
    *out_ << "\r" << text << std::string(drawn_ > text.size() ? drawn_ - text.size() : 0, ' ')
          << std::flush;
    drawn_ = text.size();
  } else {
    *out_ << text << "\n" << std::flush;
  }
  last_draw_ = Clock::now();
}

void SweepProgress::start_run(const std::string& label) {
  running_.push_back({label, Clock::now()});
  draw();
}

void SweepProgress::tick() {
  if (terminal_ && !running_.empty() && since(last_draw_) >= 1.0) draw();
}

void SweepProgress::end_run(const std::string& label, const std::string& result, double wall_time,
                            bool timed) {
  ++done_;
  const auto run = std::find_if(running_.begin(), running_.end(),
                                [&](const Running& r) { return r.label == label; });
  if (run != running_.end()) running_.erase(run);
  if (timed) {
    timed_seconds_ += wall_time;
    ++timed_runs_;
  }
  if (!out_) return;
  if (terminal_) {
    *out_ << "\r" << result << std::string(drawn_ > result.size() ? drawn_ - result.size() : 0, ' ')
          << "\n";
    drawn_ = 0;
    draw();
  } else {
    *out_ << result << "\n" << std::flush;
  }
}

void SweepProgress::finish() {
  if (!out_) return;
  running_.clear();
  if (terminal_) {
    draw();
    *out_ << "\n" << std::flush;
    drawn_ = 0;
  } else {
    draw();
  }
}

TickStream::TickStream(std::function<void()> on_write)
    : std::ostream(nullptr), buffer_(std::move(on_write)) {
  rdbuf(&buffer_);
}

TickStream::Buffer::int_type TickStream::Buffer::overflow(int_type c) {
  if (on_write_) on_write_();
  return traits_type::not_eof(c);
}

std::streamsize TickStream::Buffer::xsputn(const char*, std::streamsize n) {
  if (on_write_) on_write_();
  return n;
}

}  // namespace lituya::sweep
