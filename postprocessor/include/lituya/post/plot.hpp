#pragma once
// A small gnuplot driver. Every plot is written as an editable gnuplot script (<png stem>.gp,
// next to the PNG, reading the CSV files by paths relative to it) and then run, so a user can
// restyle a figure for a paper by editing the script and running `gnuplot runout.gp` in the
// post folder. Without gnuplot the CSV files and the scripts are still there.
#include <filesystem>
#include <string>
#include <vector>

namespace lituya::post {

struct PlotSeries {
  std::filesystem::path csv;  // comma separated, one header line
  int x_column, y_column;     // 1-based, as gnuplot counts them; see csv_column()
  std::string label;
  bool points = false;  // points (measurements) instead of lines (simulation)
  // When select_column > 0, only the rows whose select_column equals select_value (to a
  // relative 1e-9) are drawn: one curve per time out of a table of several times.
  int select_column = 0;
  double select_value = 0;
  // gnuplot line type (colour) when > 0, so that a measurement and its reference points
  // share a colour; 0 takes the next one in turn.
  int line_type = 0;
};

// 1-based number of the column called `name` in the header line of `csv`; InputError naming
// the file when there is no such column.
int csv_column(const std::filesystem::path& csv, const std::string& name);

// Writes <png without extension>.gp and runs gnuplot on it (terminal pngcairo size 900,600).
// A line break in `title` starts a new title line (e.g. the errors against the reference).
// Returns true when the PNG was made. When gnuplot is not on PATH, warns once on stderr and
// returns false; a gnuplot failure also returns false, with a warning naming the script.
// `y_from_zero` starts the y axis at 0 (heights and thicknesses, whose zero means something).
bool plot_xy(const std::filesystem::path& png, const std::string& title, const std::string& xlabel,
             const std::string& ylabel, const std::vector<PlotSeries>& series,
             bool y_from_zero = false);

// True when an executable `gnuplot` is on PATH.
bool gnuplot_available();

// `text` as a gnuplot string expression: single-quoted (taken literally), with each line break
// of `text` joined in as "\n", so a title can have several lines.
std::string gnuplot_text(const std::string& text);

// Writes `script` (a complete gnuplot script whose output is the PNG `png`, reading its data
// by paths relative to the PNG's folder) to <png without extension>.gp and runs gnuplot on it
// in that folder. Returns true when the PNG was made; false, with the warnings of plot_xy(),
// when gnuplot is missing or fails.
bool run_gnuplot_script(const std::filesystem::path& png, const std::string& script);

// `file` relative to `folder` when possible (for data paths inside scripts), else absolute.
std::string path_from(const std::filesystem::path& folder, const std::filesystem::path& file);

}  // namespace lituya::post
