#pragma once
// What a sweep plots against its parameter: one number per run, read from the CSV tables
// that `lituya post` wrote into the run's case/post folder.
//
//   gauge_max[:GAUGE]          highest eta at the gauge over the run (gauges.csv)
//   gauge_first_crest[:GAUGE]  height of the first wave crest at the gauge (gauges.csv; the
//                              rule is at kCrestOnset below)
//   gauge_first_wave_area[:GAUGE]  integral of eta over that first wave, in m s (times the
//                              wave's celerity: its volume per unit width)
//   leading_wave_max           highest crest_height of the leading wave (leading_wave.csv)
//   front_travel_final         front_travel at the last output (runout.csv)
//   front_travel_max           highest front_travel (runout.csv)
//   mass_front_travel_final    mass_front_travel at the last output (runout.csv): how far the
//                              front of 99 % of the slide's mass has moved, a measure that
//                              converges with the cell size where front_travel may not
//   wall_height_final          wall_height at the last output (wall_height.csv)
//   wall_height_max            highest wall_height (wall_height.csv)
//   kinetic_energy_solid_max   highest kinetic energy of the solid points, J (J/m in 2D),
//                              from the solver's output/<stage>_history.csv: the stage
//                              `lituya post` reads, or without [post] the scene's last;
//                              needs no [post] key
//   kinetic_energy_liquid_max  the same for the liquid points
//   speed_solid_max            highest speed of any solid point, m/s, from the same history
//                              (about a thousand rows per stage): a point thrown faster than
//                              the flow can move it shows here, where a runout may not
//   speed_liquid_max           the same for the liquid points
//
// A gauge measure without :GAUGE stands for one measure per gauge of the scene. All measures
// but gauge_first_wave_area, the kinetic energies and the speeds are lengths in m. A measure
// without a value (no water ever reached the gauge, no crest, a blank last row) is NaN, a blank
// cell in sweep.csv.
// The kinetic energies are in J (per metre of width in 2D), the speeds in m/s.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace lituya::sweep {

enum class Reduction { kLast, kMax, kFirstCrest, kFirstWaveArea };

struct Measure {
  std::string name;    // the sweep.csv column, e.g. "gauge_first_crest:G1"
  std::string csv;     // the file, relative to the post folder, e.g. "gauges.csv"
  std::string column;  // its column, e.g. "G1"
  Reduction reduction = Reduction::kLast;
  bool text_columns = false;  // the table has text columns (a history's stage name): NaN
};

// What the scene's [post] table asks `lituya post` to write.
struct PostContent {
  bool present = false;                  // the scene has a [post] table
  int line = 0;                          // of [post]
  std::vector<std::string> gauge_names;  // gauge_names, or the defaults "x=<gauges[i]>"
  bool slide = false;                    // track_materials names a material
  bool leading_wave = false;
  std::string stage;  // whose history the kinetic energy measures read (post_content sets it)
};
PostContent post_content(const toml::table& scene);

// The measure names a user may give, for messages.
std::string measure_list();

// The unit of a measure's values, from its kind ("gauge_first_wave_area:X1" -> "m s"); "m"
// for the lengths.
std::string measure_unit(const std::string& name);

// Expands and checks the measures given by the user (each "KIND" or "KIND:GAUGE") against the
// scene's [post]. InputError naming `scene_file` when a measure needs a table the scene does
// not ask for, or a gauge it does not have; an unknown KIND is an InputError naming
// --measure.
std::vector<Measure> parse_measures(const std::vector<std::string>& specs, const PostContent& post,
                                    const std::string& scene_file);

// The measures taken when none is given: gauge_first_crest at every gauge when the scene has
// gauges, else front_travel_final when it tracks a slide, else leading_wave_max when it
// follows the leading wave, else none.
std::vector<Measure> default_measures(const PostContent& post);

// A CSV table as `lituya post` writes it: a header line, then numbers; a blank field is NaN.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  // The values of `name`; InputError naming `file` when there is no such column.
  std::vector<double> column(const std::string& name, const std::string& file) const;
};
// A field that is not a number is an InputError naming the file and line, or NaN with
// `text_as_nan`.
CsvTable read_csv(const std::filesystem::path& file, bool text_as_nan = false);

// gauge_first_crest is the height of post::first_wave_crest() (the highest sample of the
// first wave, from its first sample above kCrestOnset to the record's next fall below still
// water), NaN when the water never rose kCrestOnset above still water.
inline constexpr double kCrestOnset = 0.001;  // m

// The measure's value for the run whose post folder is `post_folder`. InputError naming the
// file when the table or its column is missing.
double take_measure(const Measure& measure, const std::filesystem::path& post_folder);

}  // namespace lituya::sweep
