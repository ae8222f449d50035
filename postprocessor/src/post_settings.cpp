// Reading what the user (through the preprocessor) asked `lituya post` to measure, and the
// reference data the measurements are compared with.
#include <algorithm>
#include <charconv>
#include <fstream>
#include <sstream>

#include "lituya/common/input_error.hpp"
#include "lituya/common/toml_reader.hpp"
#include "lituya/post/postprocess.hpp"

namespace lituya::post {

namespace fs = std::filesystem;

PostSettings read_post_settings(const fs::path& post_toml) {
  TomlDocument document(post_toml);
  TomlTable root = document.root();
  TomlDocument::check_header(root, "lituya-post", 1);

  PostSettings s;
  s.file = post_toml.string();

  std::vector<double> origin = root.numbers("slope_origin");
  if (origin.size() != 2 && origin.size() != 3)
    root.fail("'slope_origin' must have 2 or 3 coordinates (x, y[, z]), found " +
                  std::to_string(origin.size()),
              "slope_origin");
  for (size_t i = 0; i < origin.size(); ++i) s.slope_origin[i] = origin[i];

  // A slope of 90 degrees or more has no downslope direction towards +x.
  s.slope_angle_deg = root.number_in("slope_angle", 0.0, 89.0);

  s.track_materials = root.strings("track_materials");
  s.track_materials_line = root.line_of("track_materials");
  if (s.track_materials.empty())
    root.fail(
        "'track_materials' is empty: name the materials whose front and thickness are "
        "measured",
        "track_materials");

  if (root.has("initial_front")) s.initial_front = root.number("initial_front");
  s.wall_position = root.number_or("wall_position", 0.0);

  s.bin_width = root.number_or("bin_width", s.bin_width);
  if (!(s.bin_width > 0))
    root.fail("'bin_width' must be > 0 (an along-slope length in m)", "bin_width");

  long long min_points = root.integer_or("min_points", s.min_points);
  if (min_points < 1 || min_points > 1000000)
    root.fail("'min_points' must be between 1 and 1000000", "min_points");
  s.min_points = static_cast<int>(min_points);

  s.profile_times = root.numbers_or("profile_times", {});
  for (double t : s.profile_times)
    if (!(t >= 0))
      root.fail("'profile_times' must all be >= 0 (stage times in s)", "profile_times");

  s.stage = root.string_or("stage", s.stage);
  s.stage_line = root.line_of("stage");
  if (s.stage.empty()) root.fail("'stage' must name a stage of stages.toml", "stage");

  if (root.has("reference")) {
    std::string reference = root.string("reference");
    if (reference.empty())
      root.fail("'reference' is empty: give a CSV file or omit the key", "reference");
    fs::path file = fs::path(reference);
    if (file.is_relative()) file = post_toml.parent_path() / file;
    file = fs::absolute(file).lexically_normal();
    if (!fs::is_regular_file(file))
      root.fail("reference file " + file.string() + " does not exist (paths are relative to " +
                    "post.toml)",
                "reference");
    s.reference_file = file.string();
  }

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

}  // namespace

ReferenceData read_reference(const fs::path& csv) {
  std::ifstream in(csv);
  if (!in) throw InputError(csv.string(), 0, "cannot open the reference data file");
  ReferenceData data;
  // Without a header the columns are time,front_travel,wall_height, as the manual says.
  int time_column = 0, front_column = 1, wall_column = 2;
  bool first_row = true;
  std::string line;
  for (int line_number = 1; std::getline(in, line); ++line_number) {
    std::string content = trimmed(line);
    if (content.empty() || content[0] == '#') continue;
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(trimmed(field));
    if (!line.empty() && line.back() == ',') fields.emplace_back();

    if (first_row && !fields.empty() && !parse_number(fields[0])) {
      time_column = front_column = wall_column = -1;
      for (int c = 0; c < static_cast<int>(fields.size()); ++c) {
        if (fields[c] == "time") time_column = c;
        if (fields[c] == "front_travel") front_column = c;
        if (fields[c] == "wall_height") wall_column = c;
      }
      if (time_column < 0)
        throw InputError(csv.string(), line_number,
                         "the header has no 'time' column (expected "
                         "time,front_travel,wall_height)");
      first_row = false;
      continue;
    }
    first_row = false;

    auto field = [&](int column, const char* what) -> std::optional<double> {
      if (column < 0 || column >= static_cast<int>(fields.size()) || fields[column].empty())
        return std::nullopt;
      auto value = parse_number(fields[column]);
      if (!value)
        throw InputError(csv.string(), line_number,
                         std::string("'") + what + "' value \"" + fields[column] +
                             "\" is not a number (leave the field blank for no value)");
      return value;
    };
    auto time = field(time_column, "time");
    if (!time) throw InputError(csv.string(), line_number, "a row without a time");
    data.time.push_back(*time);
    data.front_travel.push_back(field(front_column, "front_travel"));
    data.wall_height.push_back(field(wall_column, "wall_height"));
  }
  return data;
}

}  // namespace lituya::post
