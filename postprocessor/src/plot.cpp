#include "lituya/post/plot.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <mutex>
#include <sstream>
#include <string_view>

#include "lituya/common/atomic_file.hpp"
#include "lituya/common/input_error.hpp"

namespace lituya::post {

namespace fs = std::filesystem;

namespace {

// gnuplot single-quoted strings take everything literally except '' for a quote.
std::string gnuplot_quoted(const std::string& text) {
  std::string q = "'";
  for (char c : text) q += (c == '\'') ? std::string("''") : std::string(1, c);
  return q + "'";
}

std::string shell_quoted(const std::string& text) {
  std::string q = "'";
  for (char c : text) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

// As many digits as the CSV tables hold, so the script reads like the data it selects from.
std::string number_text(double v) {
  std::ostringstream s;
  s.precision(10);
  s << v;
  return s.str();
}

}  // namespace

// The script refers to data relative to its own folder, so the post folder can be moved or
// archived and the scripts still run in it.
std::string path_from(const fs::path& folder, const fs::path& file) {
  std::error_code ec;
  fs::path rel = fs::relative(fs::absolute(file), fs::absolute(folder), ec);
  if (ec || rel.empty()) return fs::absolute(file).string();
  return rel.string();
}

std::string gnuplot_text(const std::string& text) {
  std::string out;
  size_t start = 0;
  while (true) {
    const size_t end = text.find('\n', start);
    out += gnuplot_quoted(text.substr(start, end - start));
    if (end == std::string::npos) return out;
    out += ".\"\\n\".";
    start = end + 1;
  }
}

bool gnuplot_available() {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::string_view rest(path);
  while (true) {
    size_t colon = rest.find(':');
    // An empty PATH entry means the current folder.
    const std::string_view dir = rest.substr(0, colon);
    const fs::path candidate = (dir.empty() ? fs::path(".") : fs::path(dir)) / "gnuplot";
    if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return true;
    if (colon == std::string_view::npos) return false;
    rest.remove_prefix(colon + 1);
  }
}

int csv_column(const fs::path& csv, const std::string& name) {
  std::ifstream in(csv);
  if (!in) throw InputError(csv.string(), 0, "cannot open CSV file");
  std::string header;
  std::getline(in, header);
  if (!header.empty() && header.back() == '\r') header.pop_back();
  std::stringstream fields(header);
  std::string field;
  for (int column = 1; std::getline(fields, field, ','); ++column) {
    // Header fields may be padded or quoted by spreadsheets.
    size_t b = field.find_first_not_of(" \t\"");
    size_t e = field.find_last_not_of(" \t\"");
    if (b != std::string::npos && field.substr(b, e - b + 1) == name) return column;
  }
  throw InputError(csv.string(), 1, "no column named '" + name + "' in the header line");
}

bool plot_xy(const fs::path& png, const std::string& title, const std::string& xlabel,
             const std::string& ylabel, const std::vector<PlotSeries>& series, bool y_from_zero) {
  const fs::path folder = png.has_parent_path() ? png.parent_path() : fs::path(".");
  fs::path script = png;
  script.replace_extension(".gp");

  std::ostringstream gp;
  gp << "# Written by `lituya post`; edit and re-run in this folder: gnuplot "
     << script.filename().string() << "\n"
     << "set terminal pngcairo size 900,600 noenhanced\n"
     << "set output " << gnuplot_quoted(png.filename().string()) << "\n"
     << "set datafile separator ','\n"
     << "set title " << gnuplot_text(title) << "\n"
     << "set xlabel " << gnuplot_quoted(xlabel) << "\n"
     << "set ylabel " << gnuplot_quoted(ylabel) << "\n"
     << "set grid\n"
     // Below the axes the legend never hides a curve, whatever shape the data takes.
     << "set key below\n"
     << "set offsets graph 0.02, graph 0.02, graph 0.05, 0\n";
  if (y_from_zero) gp << "set yrange [0:*]\n";
  if (series.empty()) {
    // gnuplot refuses an empty plot command; an empty frame still tells the user that
    // there was nothing to draw.
    gp << "set label 1 'no data' at graph 0.5, graph 0.5 center\n"
       << "plot [0:1] [0:1] NaN notitle\n";
  } else {
    gp << "plot \\\n";
    for (size_t i = 0; i < series.size(); ++i) {
      const PlotSeries& s = series[i];
      // The y expression: the column, or NaN (not drawn) outside the selected rows.
      std::ostringstream y;
      if (s.select_column > 0) {
        const std::string v = number_text(s.select_value);
        y << "(abs($" << s.select_column << " - (" << v << ")) <= 1e-9 * (1 + abs(" << v << ")) ? $"
          << s.y_column << " : NaN)";
      } else {
        y << "($" << s.y_column << ")";
      }
      gp << "  " << gnuplot_quoted(path_from(folder, s.csv)) << " skip 1 using " << s.x_column
         << ":" << y.str() << (s.points ? " with points pt 7 ps 1.2" : " with lines lw 2")
         << (s.line_type > 0 ? " lt " + std::to_string(s.line_type) : std::string()) << " title "
         << gnuplot_quoted(s.label) << (i + 1 < series.size() ? ", \\\n" : "\n");
    }
  }
  return run_gnuplot_script(png, gp.str());
}

bool run_gnuplot_script(const fs::path& png, const std::string& text) {
  const fs::path folder = png.has_parent_path() ? png.parent_path() : fs::path(".");
  fs::path script = png;
  script.replace_extension(".gp");
  write_file_atomically(script, text);

  if (!gnuplot_available()) {
    static std::once_flag warned;
    std::call_once(warned, [] {
      std::cerr << "warning: gnuplot is not installed (or not on PATH); the CSV tables and the "
                   "gnuplot scripts (.gp) are written, the PNG plots are not\n";
    });
    return false;
  }
  std::error_code ec;
  fs::remove(png, ec);  // a stale PNG must not pass for a fresh one
  std::string command = "cd " + shell_quoted(fs::absolute(folder).string()) + " && gnuplot " +
                        shell_quoted(script.filename().string()) + " >/dev/null 2>" +
                        shell_quoted(script.filename().string() + ".log");
  int status = std::system(command.c_str());
  std::error_code size_error;
  const bool made = status == 0 && fs::file_size(png, size_error) > 0 && !size_error;
  fs::path log = folder / (script.filename().string() + ".log");
  if (made) {
    fs::remove(log, ec);
  } else {
    std::cerr << "warning: gnuplot failed on " << script.string() << " (messages in "
              << log.string() << ")\n";
  }
  return made;
}

}  // namespace lituya::post
