// Reading what the user (through the preprocessor) asked `lituya post` to measure, and the
// reference data the measurements are compared with.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "lituya/common/input_error.hpp"
#include "lituya/common/toml_reader.hpp"
#include "lituya/post/postprocess.hpp"

namespace lituya::post {

namespace fs = std::filesystem;

namespace {

// A data file named in post.toml (or the scene's [post]): resolved against that file's
// folder, and it must exist.
std::string referenced_file(const TomlTable& root, const fs::path& post_toml, const char* key) {
  const std::string name = root.string(key);
  if (name.empty())
    root.fail(std::string("'") + key + "' is empty: give a CSV file or omit the key", key);
  fs::path file = fs::path(name);
  if (file.is_relative()) file = post_toml.parent_path() / file;
  file = fs::absolute(file).lexically_normal();
  if (!fs::is_regular_file(file))
    root.fail(std::string(key) + " file " + file.string() +
                  " does not exist (paths are relative to " + post_toml.filename().string() + ")",
              key);
  return file.string();
}

// Gauges, leading wave and the liquid series. Read before the slide keys: whether the water
// is measured decides whether the slide keys are required.
void read_water_settings(const TomlTable& root, const fs::path& post_toml, PostSettings& s) {
  if (root.has("gauges")) {
    s.gauges = root.numbers("gauges");
    for (double x : s.gauges)
      if (!std::isfinite(x)) root.fail("'gauges' must all be finite x positions in m", "gauges");
  }
  if (root.has("gauge_names")) {
    s.gauge_names = root.strings("gauge_names");
    if (s.gauge_names.size() != s.gauges.size())
      root.fail("'gauge_names' has " + std::to_string(s.gauge_names.size()) + " names for " +
                    std::to_string(s.gauges.size()) + " gauges (one name per 'gauges' entry)",
                "gauge_names");
    // The names head the columns of gauges.csv and of the reference CSV.
    for (const std::string& name : s.gauge_names)
      if (name.empty() || name == "time" || name.find_first_of(",\"\r\n") != std::string::npos)
        root.fail("gauge name \"" + name +
                      "\" cannot head a CSV column (it must be non-empty, not \"time\", and "
                      "hold no comma, quote or line break)",
                  "gauge_names");
  } else {
    for (double x : s.gauges) {
      char name[40];
      std::snprintf(name, sizeof name, "x=%g", x);
      s.gauge_names.push_back(name);
    }
  }
  for (size_t i = 0; i < s.gauge_names.size(); ++i)
    for (size_t j = 0; j < i; ++j)
      if (s.gauge_names[i] == s.gauge_names[j])
        root.fail("two gauges are called \"" + s.gauge_names[i] + "\" (give distinct " +
                      (root.has("gauge_names") ? "names" : "positions, or gauge_names") + ")",
                  root.has("gauge_names") ? "gauge_names" : "gauges");

  s.leading_wave = root.boolean_or("leading_wave", false);
  s.leading_wave_start = root.number_or("leading_wave_start", s.leading_wave_start);
  if (!std::isfinite(s.leading_wave_start))
    root.fail("'leading_wave_start' must be a finite x position in m", "leading_wave_start");
  s.leading_wave_min_height = root.number_or("leading_wave_min_height", s.leading_wave_min_height);
  s.surface_min_porosity = root.number_or("surface_min_porosity", s.surface_min_porosity);
  if (!(s.surface_min_porosity >= 0 && s.surface_min_porosity <= 1))
    root.fail("'surface_min_porosity' must lie in [0, 1] (0 counts all water, pore water too)",
              "surface_min_porosity");
  if (!(s.leading_wave_min_height > 0) || !std::isfinite(s.leading_wave_min_height))
    root.fail("'leading_wave_min_height' must be > 0 (a wave height in m)",
              "leading_wave_min_height");

  // The key that asked for the water, where a missing liquid series is reported.
  const char* asked_by = !s.gauges.empty() ? "gauges" : "leading_wave";
  if (root.has("still_water_level")) {
    s.still_water_level = root.number("still_water_level");
    if (!std::isfinite(s.still_water_level))
      root.fail("'still_water_level' must be a finite elevation (y) in m", "still_water_level");
  } else if (s.measures_water()) {
    root.fail(std::string("'") + asked_by +
                  "' measures the water surface above still water, but 'still_water_level' "
                  "(the y of the still surface, m) is missing",
              asked_by);
  }
  if (root.has("gauge_half_width")) {
    s.gauge_half_width = root.number("gauge_half_width");
    if (!(*s.gauge_half_width > 0) || !std::isfinite(*s.gauge_half_width))
      root.fail("'gauge_half_width' must be > 0 (a length in m)", "gauge_half_width");
  }

  s.liquid_stage = root.string_or("liquid_stage", s.stage);
  if (s.liquid_stage.empty())
    root.fail("'liquid_stage' must name a stage of stages.toml", "liquid_stage");
  s.water_line = root.line_of(root.has("liquid_stage") ? "liquid_stage" : asked_by);

  if (root.has("gauge_reference")) {
    if (s.gauges.empty())
      root.fail(
          "'gauge_reference' holds wave gauge data, but there are no 'gauges' to compare "
          "it with",
          "gauge_reference");
    s.gauge_reference_file = referenced_file(root, post_toml, "gauge_reference");
  }
}

// The slope frame and the tracked materials. Required when the water is not measured (a dry
// case), optional otherwise: a water-only case has no slide to follow.
void read_slide_settings(const TomlTable& root, const fs::path& post_toml, PostSettings& s) {
  if (s.measures_water()) {
    s.track_materials = root.strings_or("track_materials", {});
  } else {
    // Said in full, because a misspelt water key (say `gauge = [...]`) also lands here.
    if (!root.has("track_materials"))
      root.fail(
          "post.toml measures nothing: give 'track_materials' (the materials whose runout is "
          "measured) or, for water, 'gauges' or 'leading_wave = true'");
    s.track_materials = root.strings("track_materials");
    if (s.track_materials.empty())
      root.fail(
          "'track_materials' is empty: name the materials whose front and thickness are "
          "measured",
          "track_materials");
  }
  s.track_materials_line = root.line_of("track_materials");

  if (s.measures_slide() || root.has("slope_origin")) {
    std::vector<double> origin = root.numbers("slope_origin");
    if (origin.size() != 2 && origin.size() != 3)
      root.fail("'slope_origin' must have 2 or 3 coordinates (x, y[, z]), found " +
                    std::to_string(origin.size()),
                "slope_origin");
    for (size_t i = 0; i < origin.size(); ++i) s.slope_origin[i] = origin[i];
  }
  // A slope of 90 degrees or more has no downslope direction towards +x.
  if (s.measures_slide() || root.has("slope_angle"))
    s.slope_angle_deg = root.number_in("slope_angle", 0.0, 89.0);

  if (root.has("initial_front")) s.initial_front = root.number("initial_front");
  s.wall_position = root.number_or("wall_position", 0.0);

  s.bin_width = root.number_or("bin_width", s.bin_width);
  if (!(s.bin_width > 0))
    root.fail("'bin_width' must be > 0 (an along-slope length in m)", "bin_width");

  long long min_points = root.integer_or("min_points", s.min_points);
  if (min_points < 1 || min_points > 1000000)
    root.fail("'min_points' must be between 1 and 1000000", "min_points");
  s.min_points = static_cast<int>(min_points);

  if (root.has("reference")) {
    if (!s.measures_slide())
      root.fail(
          "'reference' holds runout and wall-height data, but no 'track_materials' are "
          "measured (wave gauge data go in 'gauge_reference')",
          "reference");
    s.reference_file = referenced_file(root, post_toml, "reference");
  }
}

}  // namespace

PostSettings read_post_settings(const fs::path& post_toml) {
  TomlDocument document(post_toml);
  TomlTable root = document.root();
  TomlDocument::check_header(root, "lituya-post", 1);
  return read_post_table(root, post_toml);
}

PostSettings read_post_table(const TomlTable& root, const fs::path& post_toml) {
  PostSettings s;
  s.file = post_toml.string();

  s.stage = root.string_or("stage", s.stage);
  s.stage_line = root.line_of("stage");
  if (s.stage.empty()) root.fail("'stage' must name a stage of stages.toml", "stage");

  // Profiles of the slide thickness and of the water surface are both drawn at these times.
  s.profile_times = root.numbers_or("profile_times", {});
  for (double t : s.profile_times)
    if (!(t >= 0))
      root.fail("'profile_times' must all be >= 0 (stage times in s)", "profile_times");

  read_water_settings(root, post_toml, s);
  read_slide_settings(root, post_toml, s);

  root.finish();
  return s;
}

std::vector<std::string> read_material_names(const fs::path& materials_toml) {
  TomlDocument document(materials_toml);
  TomlTable root = document.root();
  TomlDocument::check_header(root, "lituya-materials", 1);
  std::vector<std::string> names;
  // Only the names matter here; the solver's reader validates the material parameters, so
  // finish() is not called on these tables.
  for (const TomlTable& material : root.tables("material"))
    names.push_back(material.string("name"));
  if (names.empty()) root.fail("no [[material]] entries");
  return names;
}

std::vector<bool> tracked_material_mask(const PostSettings& settings,
                                        const std::vector<std::string>& material_names) {
  std::vector<bool> tracked(material_names.size(), false);
  for (const std::string& name : settings.track_materials) {
    auto found = std::find(material_names.begin(), material_names.end(), name);
    if (found == material_names.end()) {
      std::string known;
      for (const std::string& n : material_names)
        known += (known.empty() ? "\"" : ", \"") + n + "\"";
      throw InputError(settings.file, settings.track_materials_line,
                       "'track_materials' names \"" + name +
                           "\", which is not a material of this case (materials.toml has " + known +
                           ")");
    }
    tracked[found - material_names.begin()] = true;
  }
  return tracked;
}

namespace {

std::string trimmed(const std::string& text) {
  size_t b = text.find_first_not_of(" \t\r\"");
  if (b == std::string::npos) return "";
  size_t e = text.find_last_not_of(" \t\r\"");
  return text.substr(b, e - b + 1);
}

std::optional<double> parse_number(const std::string& text) {
  double value = 0;
  const char* end = text.data() + text.size();
  auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

// One line of a reference CSV, split on commas and trimmed; blank lines and '#' comments
// are skipped, so data read off a paper can carry its source.
struct CsvRow {
  int line;
  std::vector<std::string> fields;
};

std::vector<CsvRow> csv_rows(const fs::path& csv) {
  std::ifstream in(csv);
  if (!in) throw InputError(csv.string(), 0, "cannot open the reference data file");
  std::vector<CsvRow> rows;
  std::string line;
  for (int line_number = 1; std::getline(in, line); ++line_number) {
    std::string content = trimmed(line);
    if (content.empty() || content[0] == '#') continue;
    CsvRow row{line_number, {}};
    std::stringstream fields(line);
    for (std::string field; std::getline(fields, field, ',');) row.fields.push_back(trimmed(field));
    if (!line.empty() && line.back() == ',') row.fields.emplace_back();
    rows.push_back(std::move(row));
  }
  return rows;
}

bool is_header(const CsvRow& row) {
  return !row.fields.empty() && !parse_number(row.fields[0]);
}

// The value in `column` of a row; a missing or blank field is no value.
std::optional<double> csv_value(const fs::path& csv, const CsvRow& row, int column,
                                const std::string& what) {
  if (column < 0 || column >= static_cast<int>(row.fields.size()) || row.fields[column].empty())
    return std::nullopt;
  auto value = parse_number(row.fields[column]);
  if (!value)
    throw InputError(csv.string(), row.line,
                     "'" + what + "' value \"" + row.fields[column] +
                         "\" is not a number (leave the field blank for no value)");
  return value;
}

double csv_time(const fs::path& csv, const CsvRow& row, int column) {
  auto time = csv_value(csv, row, column, "time");
  if (!time) throw InputError(csv.string(), row.line, "a row without a time");
  return *time;
}

}  // namespace

ReferenceData read_reference(const fs::path& csv) {
  const std::vector<CsvRow> rows = csv_rows(csv);
  ReferenceData data;
  // Without a header the columns are time,front_travel,wall_height, as the manual says.
  int time_column = 0, front_column = 1, wall_column = 2;
  size_t first_data = 0;
  if (!rows.empty() && is_header(rows[0])) {
    time_column = front_column = wall_column = -1;
    const std::vector<std::string>& header = rows[0].fields;
    for (int c = 0; c < static_cast<int>(header.size()); ++c) {
      if (header[c] == "time") time_column = c;
      if (header[c] == "front_travel") front_column = c;
      if (header[c] == "wall_height") wall_column = c;
    }
    if (time_column < 0)
      throw InputError(csv.string(), rows[0].line,
                       "the header has no 'time' column (expected "
                       "time,front_travel,wall_height)");
    first_data = 1;
  }
  for (size_t r = first_data; r < rows.size(); ++r) {
    data.time.push_back(csv_time(csv, rows[r], time_column));
    data.front_travel.push_back(csv_value(csv, rows[r], front_column, "front_travel"));
    data.wall_height.push_back(csv_value(csv, rows[r], wall_column, "wall_height"));
  }
  return data;
}

GaugeReference read_gauge_reference(const fs::path& csv,
                                    const std::vector<std::string>& gauge_names) {
  const std::vector<CsvRow> rows = csv_rows(csv);
  std::string expected = "time";
  for (const std::string& name : gauge_names) expected += "," + name;
  // The columns are matched by name, so the header is required: gauges may be listed in any
  // order, and a misspelt gauge name must not pass unnoticed as missing data.
  if (rows.empty() || !is_header(rows[0]))
    throw InputError(csv.string(), rows.empty() ? 0 : rows[0].line,
                     "the wave gauge reference needs a header line (expected " + expected + ")");
  const std::vector<std::string>& header = rows[0].fields;
  int time_column = -1;
  std::vector<int> gauge_column(gauge_names.size(), -1);
  for (int c = 0; c < static_cast<int>(header.size()); ++c) {
    if (header[c] == "time") {
      time_column = c;
      continue;
    }
    auto found = std::find(gauge_names.begin(), gauge_names.end(), header[c]);
    if (found == gauge_names.end())
      throw InputError(csv.string(), rows[0].line,
                       "column \"" + header[c] +
                           "\" names no gauge of post.toml (expected columns " + expected + ")");
    gauge_column[found - gauge_names.begin()] = c;
  }
  if (time_column < 0)
    throw InputError(csv.string(), rows[0].line,
                     "the header has no 'time' column (expected " + expected + ")");

  GaugeReference data;
  data.value.resize(gauge_names.size());
  for (size_t r = 1; r < rows.size(); ++r) {
    data.time.push_back(csv_time(csv, rows[r], time_column));
    for (size_t g = 0; g < gauge_names.size(); ++g)
      data.value[g].push_back(csv_value(csv, rows[r], gauge_column[g], gauge_names[g]));
  }
  return data;
}

}  // namespace lituya::post
