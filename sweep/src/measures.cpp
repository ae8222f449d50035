#include "lituya/sweep/measures.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

#include "lituya/common/csv_writer.hpp"
#include "lituya/common/input_error.hpp"
#include "lituya/common/quoted_list.hpp"
#include "lituya/post/postprocess.hpp"

namespace lituya::sweep {

namespace {

struct Kind {
  const char* name;
  const char* csv;
  const char* column;  // nullptr: the gauge's name
  Reduction reduction;
  enum Needs { kGauges, kSlide, kLeadingWave, kHistory } needs;
  const char* unit = "m";
};

// The solver's own table of the stage `lituya post` reads (output/<stage>_history.csv), seen
// from the post folder: it needs no [post] key.
std::string history_table(const std::string& stage) {
  return "../output/" + stage + "_history.csv";
}

constexpr Kind kKinds[] = {
    {"gauge_max", "gauges.csv", nullptr, Reduction::kMax, Kind::kGauges},
    {"gauge_first_crest", "gauges.csv", nullptr, Reduction::kFirstCrest, Kind::kGauges},
    {"gauge_first_wave_area", "gauges.csv", nullptr, Reduction::kFirstWaveArea, Kind::kGauges,
     "m s"},
    {"leading_wave_max", "leading_wave.csv", "crest_height", Reduction::kMax, Kind::kLeadingWave},
    {"front_travel_final", "runout.csv", "front_travel", Reduction::kLast, Kind::kSlide},
    {"front_travel_max", "runout.csv", "front_travel", Reduction::kMax, Kind::kSlide},
    {"mass_front_travel_final", "runout.csv", "mass_front_travel", Reduction::kLast, Kind::kSlide},
    {"wall_height_final", "wall_height.csv", "wall_height", Reduction::kLast, Kind::kSlide},
    {"wall_height_max", "wall_height.csv", "wall_height", Reduction::kMax, Kind::kSlide},
    {"kinetic_energy_solid_max", nullptr, "kinetic_energy_solid", Reduction::kMax, Kind::kHistory,
     "J, per m in 2D"},
    {"kinetic_energy_liquid_max", nullptr, "kinetic_energy_liquid", Reduction::kMax, Kind::kHistory,
     "J, per m in 2D"},
    {"speed_solid_max", nullptr, "max_speed_solid", Reduction::kMax, Kind::kHistory, "m/s"},
    {"speed_liquid_max", nullptr, "max_speed_liquid", Reduction::kMax, Kind::kHistory, "m/s"},
};

std::string trim(const std::string& s, const char* blanks = " \t\r") {
  const size_t b = s.find_first_not_of(blanks);
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(blanks) - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

}  // namespace

std::string measure_unit(const std::string& name) {
  const std::string kind = name.substr(0, name.find(':'));
  for (const Kind& k : kKinds)
    if (kind == k.name) return k.unit;
  return "m";
}

PostContent post_content(const toml::table& scene) {
  PostContent content;
  // The stage whose history the kinetic energy measures read: the one `lituya post` reads
  // ([post] stage, with post's default), or the scene's last stage when there is no [post].
  const std::string post_default = post::PostSettings{}.stage;
  const toml::table* post = scene.get_as<toml::table>("post");
  if (!post) {
    content.stage = post_default;
    if (const toml::array* stages = scene.get_as<toml::array>("stage"); stages && !stages->empty())
      if (const toml::table* last = stages->back().as_table())
        content.stage = (*last)["name"].value_or(post_default);
    return content;
  }
  content.stage = (*post)["stage"].value_or(post_default);
  content.present = true;
  content.line = static_cast<int>(post->source().begin.line);
  if (const toml::array* gauges = post->get_as<toml::array>("gauges")) {
    const toml::array* names = post->get_as<toml::array>("gauge_names");
    for (size_t i = 0; i < gauges->size(); ++i) {
      std::optional<std::string> name;
      if (names && i < names->size()) name = names->get(i)->value<std::string>();
      if (!name) {
        char text[64];
        std::snprintf(text, sizeof text, "x=%g", gauges->get(i)->value<double>().value_or(NAN));
        name = text;
      }
      content.gauge_names.push_back(*name);
    }
  }
  if (const toml::array* track = post->get_as<toml::array>("track_materials"))
    content.slide = !track->empty();
  content.leading_wave = post->get("leading_wave") && post->get("leading_wave")->value_or(false);
  return content;
}

std::string measure_list() {
  std::string list;
  for (const Kind& k : kKinds)
    list += (list.empty() ? "" : ", ") + std::string(k.name) + (k.column ? "" : "[:GAUGE]");
  return list;
}

std::vector<Measure> parse_measures(const std::vector<std::string>& specs, const PostContent& post,
                                    const std::string& scene_file) {
  std::vector<Measure> measures;
  for (const std::string& raw : specs) {
    const std::string spec = trim(raw);
    const size_t colon = spec.find(':');
    const std::string name = spec.substr(0, colon);
    const Kind* kind = nullptr;
    for (const Kind& k : kKinds)
      if (name == k.name) kind = &k;
    if (!kind || (colon != std::string::npos && kind->column))
      throw InputError("--measure", 0,
                       "unknown measure '" + spec + "'; the measures are: " + measure_list());
    auto need = [&](bool has, const std::string& what) {
      if (!post.present)
        throw InputError(scene_file, 0,
                         "measure '" + spec +
                             "' is read from the tables of `lituya post`, but the scene has no "
                             "[post] table (add one that asks for " +
                             what + ")");
      if (!has)
        throw InputError(scene_file, post.line,
                         "measure '" + spec + "' needs " + what + " in the scene's [post] table");
    };
    switch (kind->needs) {
      case Kind::kGauges:
        need(!post.gauge_names.empty(), "gauges");
        break;
      case Kind::kSlide:
        need(post.slide, "track_materials");
        break;
      case Kind::kLeadingWave:
        need(post.leading_wave, "leading_wave = true");
        break;
      case Kind::kHistory:
        break;
    }
    if (kind->column) {
      measures.push_back({kind->name, kind->csv ? kind->csv : history_table(post.stage),
                          kind->column, kind->reduction, kind->needs == Kind::kHistory});
      continue;
    }
    std::vector<std::string> gauges = post.gauge_names;
    if (colon != std::string::npos) {
      const std::string gauge = spec.substr(colon + 1);
      if (std::find(gauges.begin(), gauges.end(), gauge) == gauges.end())
        throw InputError(scene_file, post.line,
                         "measure '" + spec + "': the scene's [post] has no gauge \"" + gauge +
                             "\" (its gauges: " + quoted_list(gauges) + ")");
      gauges = {gauge};
    }
    for (const std::string& g : gauges)
      measures.push_back({std::string(kind->name) + ":" + g, kind->csv, g, kind->reduction});
  }
  // The same measure asked for twice is one column.
  std::vector<Measure> unique;
  for (const Measure& m : measures)
    if (std::none_of(unique.begin(), unique.end(), [&](auto& u) { return u.name == m.name; }))
      unique.push_back(m);
  return unique;
}

std::vector<Measure> default_measures(const PostContent& post) {
  if (!post.gauge_names.empty()) return parse_measures({"gauge_first_crest"}, post, "");
  if (post.slide) return parse_measures({"front_travel_final"}, post, "");
  if (post.leading_wave) return parse_measures({"leading_wave_max"}, post, "");
  return {};
}

std::vector<double> CsvTable::column(const std::string& name, const std::string& file) const {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end())
    throw InputError(file, 1,
                     "no column '" + name + "' (the columns: " + quoted_list(header) + ")");
  const size_t c = static_cast<size_t>(it - header.begin());
  std::vector<double> values;
  for (const auto& row : rows) values.push_back(c < row.size() ? row[c] : NAN);
  return values;
}

CsvTable read_csv(const std::filesystem::path& file, bool text_as_nan) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string(), 0, "cannot open the table (was it written?)");
  CsvTable table;
  std::string line;
  int number = 0;
  bool header = false;
  while (std::getline(in, line)) {
    ++number;
    line = trim(line);
    if (line.empty() || line[0] == '#') continue;
    if (!header) {
      // The header as the CSV writer quotes it (a gauge name may hold a comma).
      for (const std::string& f : csv_split(line)) table.header.push_back(trim(f));
      header = true;
      continue;
    }
    std::vector<double> row;
    for (const std::string& raw : split(line)) {
      const std::string f = trim(raw);
      if (f.empty()) {
        row.push_back(NAN);
        continue;
      }
      char* end = nullptr;
      const double v = std::strtod(f.c_str(), &end);
      if (end == f.c_str() + f.size())
        row.push_back(v);
      else if (text_as_nan)
        row.push_back(NAN);
      else
        throw InputError(file.string(), number, "'" + f + "' is not a number");
    }
    table.rows.push_back(std::move(row));
  }
  if (!header) throw InputError(file.string(), 0, "empty table (no header line)");
  return table;
}

double take_measure(const Measure& measure, const std::filesystem::path& post_folder) {
  const std::filesystem::path file = (post_folder / measure.csv).lexically_normal();
  const CsvTable table = read_csv(file, measure.text_columns);
  const std::vector<double> values = table.column(measure.column, file.string());
  switch (measure.reduction) {
    case Reduction::kLast:
      return values.empty() ? NAN : values.back();
    case Reduction::kMax: {
      double best = NAN;
      for (double v : values)
        if (std::isfinite(v) && !(v <= best)) best = v;
      return best;
    }
    case Reduction::kFirstCrest:
    case Reduction::kFirstWaveArea: {
      const post::WaveCrest wave =
          post::first_wave_crest(table.column("time", file.string()), values, kCrestOnset);
      return measure.reduction == Reduction::kFirstCrest ? wave.height : wave.area;
    }
  }
  return NAN;
}

}  // namespace lituya::sweep
