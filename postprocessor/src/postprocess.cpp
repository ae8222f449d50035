// `lituya post`: runs the measurements over the whole output series of one stage (the slide
// on the point series, the water on the liquid series) and writes the tables and plots a
// user compares with the laboratory.
#include "lituya/post/postprocess.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>

#include "lituya/common/atomic_file.hpp"
#include "lituya/common/csv_writer.hpp"
#include "lituya/common/input_error.hpp"
#include "lituya/common/output_folder.hpp"
#include "lituya/common/toml_reader.hpp"
#include "lituya/post/plot.hpp"
#include "lituya/post/reference_error.hpp"
#include "lituya/post/snapshot.hpp"

namespace lituya::post {

namespace fs = std::filesystem;

namespace {

// The share of the tracked mass behind the mass front (runout.csv's mass_front_*): the front of
// the mass, less the 1 % that a run throws ahead as a thin tail or stray grains.
constexpr double kMassFrontShare = 0.99;

// A table gathered in memory and written whole by close(), through the project's CSV writer
// (RFC 4180 quoting, numbers that read back exactly, a blank field for "no value" as in the
// reference CSV, so that a time at which no front could be found plots as a gap rather than as
// a misleading number). It is written atomically: a full disk leaves the earlier table (post
// --force) or none, never a torn one.
class CsvFile {
 public:
  CsvFile(const fs::path& file, const std::vector<std::string>& header)
      : file_(file), table_(header) {}
  template <typename... Values>
  void row(const Values&... values) {
    table_.row({static_cast<double>(values)...});
  }
  void row(const std::vector<double>& values) { table_.row(values); }
  void close() { table_.write(file_); }

 private:
  fs::path file_;
  CsvWriter table_;
};

// The dimension decides how a point's volume becomes its spacing; stages.toml states it, the
// coordinates are only a fallback.
int case_dimension(const fs::path& case_folder) {
  const fs::path stages = case_folder / "stages.toml";
  if (!fs::exists(stages)) return 0;
  TomlDocument document(stages);
  TomlTable root = document.root();
  if (!root.has("dimension")) return 0;
  long long dimension = root.integer("dimension");
  if (dimension != 2 && dimension != 3) root.fail("'dimension' must be 2 or 3", "dimension");
  return static_cast<int>(dimension);
}

size_t closest_output(const std::vector<SeriesEntry>& series, double time) {
  size_t best = 0;
  for (size_t i = 1; i < series.size(); ++i)
    if (std::abs(series[i].time - time) < std::abs(series[best].time - time)) best = i;
  return best;
}

// Output written without `volume` but with `id`: take the volumes of the initial points, so
// that the thickness still includes the half spacing above the top points.
void fill_missing_volumes(PointCloud& cloud, const fs::path& case_folder,
                          std::optional<std::vector<double>>& initial_volume) {
  if (!cloud.volume.empty()) return;
  if (!initial_volume) {
    initial_volume.emplace();
    const fs::path points_vtu = case_folder / "points.vtu";
    if (fs::exists(points_vtu)) *initial_volume = read_points(points_vtu).volume;
    if (initial_volume->empty() || cloud.id.empty())
      std::cerr << "warning: the point output has no 'volume' field; thicknesses are those of "
                   "the point centres (half a point spacing too low)\n";
  }
  if (initial_volume->empty() || cloud.id.empty()) return;
  cloud.volume.resize(cloud.position.size(), 0.0);
  for (size_t i = 0; i < cloud.id.size(); ++i) {
    const int id = cloud.id[i];
    if (id >= 0 && id < static_cast<int>(initial_volume->size()))
      cloud.volume[i] = (*initial_volume)[id];
  }
}

// Everything written into the post folder is recorded, so a caller can list it.
class PostFolder {
 public:
  PostFolder(fs::path folder, PostResult& result) : folder_(std::move(folder)), result_(result) {}
  fs::path file(const std::string& name) {
    result_.files.push_back(folder_ / name);
    return folder_ / name;
  }
  // A PNG and its gnuplot script; false when the PNG could not be made.
  bool plot(const std::string& png, const std::string& title, const std::string& xlabel,
            const std::string& ylabel, const std::vector<PlotSeries>& series,
            bool y_from_zero = false) {
    result_.files.push_back((folder_ / png).replace_extension(".gp"));
    const bool made = plot_xy(folder_ / png, title, xlabel, ylabel, series, y_from_zero);
    if (made) result_.files.push_back(folder_ / png);
    return made;
  }
  const fs::path& folder() const { return folder_; }
  // A file written by someone else (the snapshots) into the folder.
  void record(const fs::path& file) { result_.files.push_back(file); }

 private:
  fs::path folder_;
  PostResult& result_;
};

// A reference column as numbers, NaN where it has no value.
std::vector<double> values_of(const std::vector<std::optional<double>>& column) {
  std::vector<double> v;
  v.reserve(column.size());
  for (const auto& x : column) v.push_back(x.value_or(std::numeric_limits<double>::quiet_NaN()));
  return v;
}

// The errors of one simulated series against its reference, recorded for errors.csv.
const ReferenceError& record_error(PostResult& result, const std::string& plot,
                                   const std::string& series, const std::vector<double>& sim_time,
                                   const std::vector<double>& sim_value,
                                   const std::vector<double>& ref_time,
                                   const std::vector<double>& ref_value) {
  ReferenceError e = compare_with_reference(sim_time, sim_value, ref_time, ref_value);
  e.plot = plot;
  e.series = series;
  e.unit = "m";
  result.errors.push_back(e);
  return result.errors.back();
}

// What the slide measures need, read and checked before the post folder is touched.
struct SlideInput {
  std::vector<std::string> material_names;
  std::vector<bool> tracked;
  SlopeFrame frame;
  std::vector<SeriesEntry> series;
  std::optional<ReferenceData> reference;
};

SlideInput read_slide_input(const PostSettings& settings, const fs::path& case_folder) {
  std::vector<std::string> material_names = read_material_names(case_folder / "materials.toml");
  std::vector<bool> tracked = tracked_material_mask(settings, material_names);
  const SlopeFrame frame(
      Eigen::Vector3d(settings.slope_origin[0], settings.slope_origin[1], settings.slope_origin[2]),
      settings.slope_angle_deg);
  const fs::path pvd = case_folder / "output" / (settings.stage + "_points.pvd");
  if (!fs::exists(pvd))
    throw InputError(settings.file, settings.stage_line,
                     "no output series for stage '" + settings.stage + "': " + pvd.string() +
                         " does not exist (run `lituya solve` first, or check the stage name)");
  std::vector<SeriesEntry> series = read_pvd(pvd);
  if (series.empty()) throw InputError(pvd.string(), 0, "the collection lists no outputs");
  std::optional<ReferenceData> reference;
  if (!settings.reference_file.empty()) reference = read_reference(settings.reference_file);
  return {std::move(material_names), std::move(tracked), frame, std::move(series),
          std::move(reference)};
}

// What the water measures need, read and checked before the post folder is touched.
struct WaterInput {
  std::vector<SeriesEntry> series;
  std::optional<GaugeReference> reference;
  double half_width = 0;  // of a gauge's column; the surface profile bins are twice as wide
  double gravity = 0;     // m/s2, |gravity|, for the leading wave's speed bound
};

WaterInput read_water_input(const PostSettings& settings, const fs::path& case_folder,
                            int dimension) {
  WaterInput input;
  const fs::path pvd = case_folder / "output" / (settings.liquid_stage + "_liquid.pvd");
  if (!fs::exists(pvd))
    throw InputError(
        settings.file, settings.water_line,
        std::string(settings.gauges.empty() ? "the leading wave needs" : "the wave gauges need") +
            " the water surface, but there is no liquid output for stage '" +
            settings.liquid_stage + "': " + pvd.string() +
            " does not exist (a case without water writes none; otherwise run "
            "`lituya solve` first, or check 'liquid_stage')");
  input.series = read_pvd(pvd);
  if (input.series.empty()) throw InputError(pvd.string(), 0, "the collection lists no outputs");
  if (!settings.gauge_reference_file.empty())
    input.reference = read_gauge_reference(settings.gauge_reference_file, settings.gauge_names);
  if (settings.leading_wave) input.gravity = case_gravity(case_folder);

  if (settings.gauge_half_width) {
    input.half_width = *settings.gauge_half_width;
  } else {
    // The spacing of the points as they were seeded (the first output that holds any), so
    // that every output is measured over the same columns.
    for (const SeriesEntry& entry : input.series) {
      const double spacing = median_point_spacing(read_liquid_points(entry.file, dimension));
      if (std::isfinite(spacing)) {
        input.half_width = spacing;
        break;
      }
    }
    if (!(input.half_width > 0))
      throw InputError(settings.file, settings.water_line,
                       "cannot infer 'gauge_half_width': no liquid output of " + pvd.string() +
                           " holds points with a volume (give gauge_half_width in m)");
  }
  return input;
}

bool measure_slide(const PostSettings& settings, const SlideInput& input,
                   const fs::path& case_folder, int dimension, PostFolder& out,
                   PostResult& result) {
  const std::vector<SeriesEntry>& series = input.series;
  std::vector<size_t> profile_output;
  for (double t : settings.profile_times) {
    profile_output.push_back(closest_output(series, t));
    result.profiles.push_back({t, series[profile_output.back()].time, {}});
  }

  std::optional<std::vector<double>> initial_volume;
  for (size_t k = 0; k < series.size(); ++k) {
    PointCloud cloud = read_points(series[k].file, dimension);
    fill_missing_volumes(cloud, case_folder, initial_volume);
    if (cloud.material.empty() && input.material_names.size() > 1)
      throw InputError(series[k].file.string(), 0,
                       "the points have no 'material' field, so the tracked materials cannot be "
                       "told apart (add \"material\" to [output] point_fields)");
    result.time.push_back(series[k].time);
    result.front_position.push_back(
        front_position(cloud, input.tracked, input.frame, settings.bin_width, settings.min_points));
    result.mass_front_position.push_back(
        mass_front_position(cloud, input.tracked, input.frame, kMassFrontShare));
    result.wall_height.push_back(wall_height(cloud, input.tracked, input.frame,
                                             settings.wall_position, settings.bin_width,
                                             settings.min_points));
    for (size_t p = 0; p < profile_output.size(); ++p)
      if (profile_output[p] == k)
        result.profiles[p].bins = thickness_profile(cloud, input.tracked, input.frame,
                                                    settings.bin_width, settings.min_points);
  }
  const double start_front = settings.initial_front.value_or(result.front_position.front());
  for (double front : result.front_position) result.front_travel.push_back(front - start_front);
  for (double front : result.mass_front_position)
    result.mass_front_travel.push_back(front - result.mass_front_position.front());

  // Tables.
  const fs::path runout_csv = out.file("runout.csv");
  const fs::path wall_csv = out.file("wall_height.csv");
  const fs::path profiles_csv = out.file("profiles.csv");
  {
    CsvFile runout(runout_csv, {"time", "front_position", "front_travel", "mass_front_position",
                                "mass_front_travel"});
    CsvFile wall(wall_csv, {"time", "wall_height"});
    for (size_t k = 0; k < result.time.size(); ++k) {
      runout.row(result.time[k], result.front_position[k], result.front_travel[k],
                 result.mass_front_position[k], result.mass_front_travel[k]);
      wall.row(result.time[k], result.wall_height[k]);
    }
    runout.close();
    wall.close();
  }
  // Two requested times may fall on the same output: its profile is written once.
  std::vector<double> profile_times_written;
  {
    CsvFile profiles(profiles_csv, {"time", "s", "thickness"});
    std::set<double> written;
    for (const TimedProfile& profile : result.profiles) {
      if (!written.insert(profile.time).second) continue;
      profile_times_written.push_back(profile.time);
      for (const ProfileBin& bin : profile.bins) profiles.row(profile.time, bin.s, bin.thickness);
    }
    profiles.close();
  }

  // Reference data: a verbatim copy, and one table per measurement holding only the rows with
  // a value, which is what the plots draw as points.
  fs::path reference_runout_csv, reference_wall_csv;
  if (input.reference) {
    const fs::path copy = out.file("reference.csv");
    std::error_code same;
    if (!fs::equivalent(settings.reference_file, copy, same))
      copy_file_atomically(settings.reference_file, copy);
    reference_runout_csv = out.file("reference_runout.csv");
    reference_wall_csv = out.file("reference_wall_height.csv");
    CsvFile runout(reference_runout_csv, {"time", "front_travel"});
    CsvFile wall(reference_wall_csv, {"time", "wall_height"});
    const ReferenceData& reference = *input.reference;
    for (size_t k = 0; k < reference.time.size(); ++k) {
      if (reference.front_travel[k]) runout.row(reference.time[k], *reference.front_travel[k]);
      if (reference.wall_height[k]) wall.row(reference.time[k], *reference.wall_height[k]);
    }
    runout.close();
    wall.close();
  }

  // Plots.
  const std::string stage = " (stage '" + settings.stage + "')";
  std::vector<PlotSeries> runout_series{{runout_csv, 1, 3, "Lituya (MPM)"}};
  if (std::any_of(result.mass_front_travel.begin(), result.mass_front_travel.end(),
                  [](double v) { return std::isfinite(v); }))
    runout_series.push_back({runout_csv, 1, 5, "Lituya, front of 99 % of the mass"});
  std::vector<PlotSeries> wall_series{{wall_csv, 1, 2, "Lituya (MPM)"}};
  if (input.reference) {
    runout_series.push_back({reference_runout_csv, 1, 2, "reference", true});
    wall_series.push_back({reference_wall_csv, 1, 2, "reference", true});
  }
  std::vector<PlotSeries> profile_series;
  for (double t : profile_times_written) {
    char label[48];
    std::snprintf(label, sizeof label, "t = %g s", t);
    profile_series.push_back({profiles_csv, 2, 3, label, false, 1, t});
  }
  // Against a reference, the title carries the errors (reference_error.hpp).
  std::string runout_title = "Front travel along the slope" + stage;
  std::string wall_title = "Height of the mass at the wall" + stage;
  if (input.reference) {
    const ReferenceData& reference = *input.reference;
    runout_title +=
        "\n" + error_summary(record_error(result, "runout.png", "front_travel", result.time,
                                          result.front_travel, reference.time,
                                          values_of(reference.front_travel)));
    wall_title += "\n" + error_summary(record_error(result, "wall_height.png", "wall_height",
                                                    result.time, result.wall_height, reference.time,
                                                    values_of(reference.wall_height)));
  }
  bool plotted =
      out.plot("runout.png", runout_title, "time (s)", "front travel (m)", runout_series);
  plotted = out.plot("wall_height.png", wall_title, "time (s)", "height normal to the slope (m)",
                     wall_series, true) &&
            plotted;
  plotted =
      out.plot("profiles.png", "Thickness along the slope" + stage, "along-slope distance s (m)",
               "thickness normal to the slope (m)", profile_series, true) &&
      plotted;
  return plotted;
}

// The liquid points of the free water: pore water (porosity below `min_porosity`) has no free
// surface of its own, and a saturated slide standing above the lake must not read as a wave.
PointCloud free_water(PointCloud cloud, double min_porosity) {
  if (cloud.porosity.empty() || min_porosity <= 0) return cloud;
  PointCloud out;
  out.dimension = cloud.dimension;
  for (size_t i = 0; i < cloud.position.size(); ++i) {
    if (cloud.porosity[i] < min_porosity) continue;
    out.position.push_back(cloud.position[i]);
    if (!cloud.material.empty()) out.material.push_back(cloud.material[i]);
    if (!cloud.volume.empty()) out.volume.push_back(cloud.volume[i]);
    if (!cloud.id.empty()) out.id.push_back(cloud.id[i]);
    out.porosity.push_back(cloud.porosity[i]);
    if (!cloud.speed.empty()) out.speed.push_back(cloud.speed[i]);
  }
  return out;
}

bool measure_water(const PostSettings& settings, const WaterInput& input, int dimension,
                   PostFolder& out, PostResult& result) {
  const std::vector<SeriesEntry>& series = input.series;
  const size_t gauges = settings.gauges.size();
  const double bin_width = 2 * input.half_width;
  result.gauge_names = settings.gauge_names;
  result.gauge_half_width = input.half_width;
  result.gauge_eta.assign(gauges, {});

  std::vector<size_t> profile_output;
  for (double t : settings.profile_times) {
    profile_output.push_back(closest_output(series, t));
    result.surface_profiles.push_back({t, series[profile_output.back()].time, {}});
  }

  // The leading wave is tracked over the whole record once it is read: one profile per output.
  std::vector<std::vector<SurfaceBin>> wave_profiles;
  double depth = NAN;  // of the still water, from the first output with water (the lake at rest),
                       // for the tracker's speed bound
  for (size_t k = 0; k < series.size(); ++k) {
    const PointCloud liquid =
        free_water(read_liquid_points(series[k].file, dimension), settings.surface_min_porosity);
    if (settings.leading_wave && std::isnan(depth))
      depth = still_water_depth(liquid, settings.still_water_level);
    result.liquid_time.push_back(series[k].time);
    for (size_t g = 0; g < gauges; ++g)
      result.gauge_eta[g].push_back(gauge_elevation(liquid, settings.gauges[g], input.half_width,
                                                    settings.still_water_level));
    const bool profile_wanted =
        std::find(profile_output.begin(), profile_output.end(), k) != profile_output.end();
    if (!settings.leading_wave && !profile_wanted) continue;
    // Anchored on leading_wave_start, so the crest search starts on a bin edge.
    std::vector<SurfaceBin> profile =
        surface_profile(liquid, settings.leading_wave_start, bin_width, settings.still_water_level);
    for (size_t p = 0; p < profile_output.size(); ++p)
      if (profile_output[p] == k) result.surface_profiles[p].bins = profile;
    if (settings.leading_wave) wave_profiles.push_back(std::move(profile));
  }
  if (settings.leading_wave)
    for (const LeadingWave& wave :
         track_leading_wave(result.liquid_time, wave_profiles, settings.leading_wave_start,
                            settings.leading_wave_min_height, depth, input.gravity)) {
      result.crest_x.push_back(wave.crest_x);
      result.crest_eta.push_back(wave.crest_eta);
      result.max_eta.push_back(wave.max_eta);
    }

  const std::string stage = " (stage '" + settings.liquid_stage + "')";
  bool plotted = true;

  if (gauges > 0) {
    const fs::path gauges_csv = out.file("gauges.csv");
    std::vector<std::string> header{"time"};
    header.insert(header.end(), settings.gauge_names.begin(), settings.gauge_names.end());
    CsvFile table(gauges_csv, header);
    for (size_t k = 0; k < result.liquid_time.size(); ++k) {
      std::vector<double> row{result.liquid_time[k]};
      for (size_t g = 0; g < gauges; ++g) row.push_back(result.gauge_eta[g][k]);
      table.row(row);
    }
    table.close();

    std::vector<PlotSeries> plot_series;
    for (size_t g = 0; g < gauges; ++g) {
      const int colour = static_cast<int>(g) + 1;
      plot_series.push_back({gauges_csv, 1, colour + 1, settings.gauge_names[g]});
      plot_series.back().line_type = colour;
    }
    // Reference: a verbatim copy, and per gauge a table of the rows with a value; the errors
    // of each gauge go into the title.
    std::string title = "Water surface at the wave gauges" + stage;
    if (input.reference) {
      const fs::path copy = out.file("gauge_reference.csv");
      std::error_code same;
      if (!fs::equivalent(settings.gauge_reference_file, copy, same))
        copy_file_atomically(settings.gauge_reference_file, copy);
      for (size_t g = 0; g < gauges; ++g) {
        const GaugeReference& reference = *input.reference;
        bool any = false;
        for (const auto& v : reference.value[g]) any = any || v.has_value();
        if (!any) continue;
        // By index, not by name: a gauge name need not make a valid file name.
        const fs::path csv = out.file("reference_gauge_" + std::to_string(g + 1) + ".csv");
        CsvFile table_g(csv, {"time", settings.gauge_names[g]});
        for (size_t r = 0; r < reference.time.size(); ++r)
          if (reference.value[g][r]) table_g.row(reference.time[r], *reference.value[g][r]);
        table_g.close();
        plot_series.push_back({csv, 1, 2, settings.gauge_names[g] + " (reference)", true});
        plot_series.back().line_type = static_cast<int>(g) + 1;
        title += "\n" + error_summary(record_error(result, "gauges.png", settings.gauge_names[g],
                                                   result.liquid_time, result.gauge_eta[g],
                                                   reference.time, values_of(reference.value[g])),
                                      settings.gauge_names[g]);
      }
    }
    plotted =
        out.plot("gauges.png", title, "time (s)", "elevation above still water (m)", plot_series) &&
        plotted;
  }

  if (settings.leading_wave) {
    const fs::path leading_csv = out.file("leading_wave.csv");
    CsvFile table(leading_csv, {"time", "crest_x", "crest_height", "max_eta"});
    for (size_t k = 0; k < result.liquid_time.size(); ++k)
      table.row(result.liquid_time[k], result.crest_x[k], result.crest_eta[k], result.max_eta[k]);
    table.close();
    char beyond[64];
    std::snprintf(beyond, sizeof beyond, "highest surface at x >= %g m",
                  settings.leading_wave_start);
    plotted = out.plot("leading_wave.png", "Leading wave crest height" + stage, "time (s)",
                       "elevation above still water (m)",
                       // The crest is drawn last, on top, where it is the highest surface.
                       {{leading_csv, 1, 4, beyond, false, 0, 0, 2},
                        {leading_csv, 1, 3, "leading wave crest", false, 0, 0, 1}}) &&
              plotted;
  }

  // Two requested times may fall on the same output: its profile is written once.
  const fs::path surface_csv = out.file("surface_profiles.csv");
  std::vector<PlotSeries> surface_series;
  {
    CsvFile table(surface_csv, {"time", "x", "eta"});
    std::set<double> written;
    for (const TimedSurface& profile : result.surface_profiles) {
      if (!written.insert(profile.time).second) continue;
      for (const SurfaceBin& bin : profile.bins) table.row(profile.time, bin.x, bin.eta);
      char label[48];
      std::snprintf(label, sizeof label, "t = %g s", profile.time);
      surface_series.push_back({surface_csv, 2, 3, label, false, 1, profile.time});
    }
    table.close();
  }
  plotted = out.plot("surface_profiles.png", "Water surface along the flume" + stage, "x (m)",
                     "elevation above still water (m)", surface_series) &&
            plotted;
  return plotted;
}

// The columns of a CSV table the solver wrote (header, and whether each column holds at least
// one value: a probe away from the water has no pore pressure, and gnuplot refuses a curve
// without a single point).
struct TableColumns {
  std::vector<std::string> names;
  std::vector<bool> has_value;
};
TableColumns table_columns(const fs::path& csv) {
  TableColumns t;
  std::ifstream in(csv);
  std::string line;
  if (!std::getline(in, line)) return t;
  t.names = csv_split(line);
  t.has_value.assign(t.names.size(), false);
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = csv_split(line);
    for (std::size_t k = 0; k < fields.size() && k < t.has_value.size(); ++k)
      if (!fields[k].empty()) t.has_value[k] = true;
  }
  return t;
}

// One PNG of the columns whose names start with one of `prefixes` against `x_column`; nothing
// when none holds a value. Returns false when a plot could not be made.
bool plot_columns(PostFolder& out, const fs::path& csv, const TableColumns& table,
                  const std::string& x_column, const std::vector<std::string>& prefixes,
                  const std::string& png, const std::string& title, const std::string& xlabel,
                  const std::string& ylabel, bool exact = false) {
  std::vector<PlotSeries> series;
  const auto x = std::find(table.names.begin(), table.names.end(), x_column);
  if (x == table.names.end()) return true;
  for (std::size_t k = 0; k < table.names.size(); ++k) {
    const std::string& name = table.names[k];
    const bool wanted = std::any_of(prefixes.begin(), prefixes.end(), [&](const std::string& p) {
      return name == p || (!exact && name.rfind(p + "_", 0) == 0);
    });
    if (!wanted || !table.has_value[k]) continue;
    PlotSeries s{csv, static_cast<int>(x - table.names.begin()) + 1, static_cast<int>(k) + 1, name};
    series.push_back(s);
  }
  if (series.empty()) return true;
  return out.plot(png, title, xlabel, ylabel, series);
}

// The boundaries' names in a stage history: each held boundary <name> has the columns
// wall_<name>_force_x, _y (_z), _normal, _tangential (solver/src/wall_loads.cpp). Read from
// the _force_x columns, the one suffix no other column of a boundary ends in, so a boundary
// named "bed_normal" is not taken for the normal force of one named "bed".
std::vector<std::string> wall_names(const TableColumns& table) {
  const std::string prefix = "wall_", suffix = "_force_x";
  std::vector<std::string> names;
  for (const std::string& column : table.names)
    if (column.size() > prefix.size() + suffix.size() && column.rfind(prefix, 0) == 0 &&
        column.compare(column.size() - suffix.size(), suffix.size(), suffix) == 0)
      names.push_back(column.substr(prefix.size(), column.size() - prefix.size() - suffix.size()));
  return names;
}

// One plot per held boundary: the normal force the material exerts on it, the tangential
// (friction) force and, on a contact wall in a case with water, the effective normal force
// Coulomb's law acts on. Mean forces over each row's interval, per metre in 2D.
bool plot_wall_forces(PostFolder& out, const fs::path& csv, const TableColumns& table,
                      const std::string& stem, const std::string& stage) {
  bool plotted = true;
  for (const std::string& wall : wall_names(table)) {
    const std::string w = "wall_" + wall;
    const bool three_d =
        std::find(table.names.begin(), table.names.end(), w + "_force_z") != table.names.end();
    plotted =
        plot_columns(out, csv, table, "stage_time",
                     {w + "_normal", w + "_tangential", w + "_effective_normal"},
                     stem + "_" + w + ".png", "stage " + stage + ": forces on the boundary " + wall,
                     "time in stage (s)", three_d ? "force (N)" : "force (N per m)", true) &&
        plotted;
  }
  return plotted;
}

// The probes (output/probes/<name>.csv) against the run's time, one plot per field, and each
// stage's history (output/<stage>_history.csv) against the stage's time. The plots read the
// tables where the solver wrote them.
bool plot_time_histories(const fs::path& case_folder, PostFolder& out) {
  bool plotted = true;
  const fs::path output = case_folder / "output";
  std::vector<fs::path> probes, histories;
  std::error_code error;
  if (fs::is_directory(output / "probes", error))
    for (const auto& entry : fs::directory_iterator(output / "probes"))
      if (entry.path().extension() == ".csv") probes.push_back(entry.path());
  if (fs::is_directory(output, error))
    for (const auto& entry : fs::directory_iterator(output)) {
      const std::string name = entry.path().filename().string();
      if (name.size() > 12 && name.compare(name.size() - 12, 12, "_history.csv") == 0)
        histories.push_back(entry.path());
    }
  std::sort(probes.begin(), probes.end());
  std::sort(histories.begin(), histories.end());
  struct Field {
    const char* column;
    const char* label;
  };
  constexpr Field kFields[] = {{"pore_pressure", "pore pressure (Pa, compression positive)"},
                               {"effective_stress", "effective stress (Pa, tension positive)"},
                               {"velocity", "soil velocity (m/s)"},
                               {"liquid_velocity", "water velocity (m/s)"},
                               {"porosity", "porosity (-)"}};
  for (const fs::path& csv : probes) {
    const std::string name = csv.stem().string();
    const TableColumns table = table_columns(csv);
    for (const Field& f : kFields)
      plotted = plot_columns(out, csv, table, "time", {f.column},
                             "probe_" + name + "_" + f.column + ".png",
                             "probe " + name + ": " + f.label, "time (s)", f.label) &&
                plotted;
  }
  for (const fs::path& csv : histories) {
    const std::string stem = csv.stem().string();  // <stage>_history
    const std::string stage = stem.substr(0, stem.size() - 8);
    const TableColumns table = table_columns(csv);
    plotted = plot_columns(out, csv, table, "stage_time", {"kinetic_energy"},
                           stem + "_kinetic_energy.png", "stage " + stage + ": kinetic energy",
                           "time in stage (s)", "kinetic energy (J, per m in 2D)") &&
              plotted;
    plotted =
        plot_columns(out, csv, table, "stage_time", {"time_step"}, stem + "_time_step.png",
                     "stage " + stage + ": time step", "time in stage (s)", "time step (s)") &&
        plotted;
    plotted = plot_columns(out, csv, table, "stage_time", {"max_speed"}, stem + "_max_speed.png",
                           "stage " + stage + ": largest point speed", "time in stage (s)",
                           "speed (m/s)") &&
              plotted;
    plotted = plot_wall_forces(out, csv, table, stem, stage) && plotted;
  }
  return plotted;
}

// One row per series drawn against a reference (reference_error.hpp for the definitions).
void write_errors(const std::vector<ReferenceError>& errors, PostFolder& out) {
  CsvWriter table({"plot", "series", "unit", "span_start", "span_end", "samples", "rms_error",
                   "simulated_peak", "reference_peak", "peak_error", "peak_error_relative",
                   "arrival_threshold", "simulated_arrival", "reference_arrival", "arrival_error"});
  for (const ReferenceError& e : errors) {
    table.text(e.plot).text(e.series).text(e.unit);
    table.number(e.span_start).number(e.span_end).integer(e.samples).number(e.rms);
    table.number(e.simulated_peak).number(e.reference_peak).number(e.peak_error);
    table.number(e.peak_error_relative).number(e.threshold).number(e.simulated_arrival);
    table.number(e.reference_arrival).number(e.arrival_error);
    table.end_row();
  }
  table.write(out.file("errors.csv"));
}

// The series the snapshots are drawn from: the stage's solid points and the liquid stage's
// water, whichever were written.
struct SnapshotInput {
  std::vector<SeriesEntry> solid, liquid;
  std::vector<std::string> material_names;
};

std::optional<SnapshotInput> read_snapshot_input(const PostSettings& settings,
                                                 const fs::path& case_folder,
                                                 const std::optional<SlideInput>& slide,
                                                 const std::optional<WaterInput>& water) {
  if (settings.profile_times.empty()) return std::nullopt;
  SnapshotInput input;
  const fs::path output = case_folder / "output";
  if (slide) {
    input.solid = slide->series;
    input.material_names = slide->material_names;
  } else if (fs::exists(output / (settings.stage + "_points.pvd"))) {
    input.solid = read_pvd(output / (settings.stage + "_points.pvd"));
  }
  if (water)
    input.liquid = water->series;
  else if (fs::exists(output / (settings.liquid_stage + "_liquid.pvd")))
    input.liquid = read_pvd(output / (settings.liquid_stage + "_liquid.pvd"));
  if (input.solid.empty() && input.liquid.empty()) return std::nullopt;
  if (input.material_names.empty() && fs::exists(case_folder / "materials.toml"))
    input.material_names = read_material_names(case_folder / "materials.toml");
  return input;
}

// The scene at the outputs closest to the profile times, into <post>/snapshots/.
bool draw_scene_snapshots(const PostSettings& settings, const SnapshotInput& input, int dimension,
                          PostFolder& out, PostResult& result) {
  std::vector<Snapshot> snapshots;
  std::set<std::pair<size_t, size_t>> drawn;
  const size_t none = static_cast<size_t>(-1);
  for (double t : settings.profile_times) {
    const size_t s = input.solid.empty() ? none : closest_output(input.solid, t);
    const size_t l = input.liquid.empty() ? none : closest_output(input.liquid, t);
    if (!drawn.insert({s, l}).second) continue;  // two times on the same outputs
    std::optional<PointCloud> solid, liquid;
    if (s != none) solid = read_points(input.solid[s].file, dimension);
    if (l != none) liquid = read_liquid_points(input.liquid[l].file, dimension);
    const double time = s != none ? input.solid[s].time : input.liquid[l].time;
    snapshots.push_back(
        make_snapshot(t, time, solid ? &*solid : nullptr, liquid ? &*liquid : nullptr));
  }
  const fs::path folder = out.folder() / "snapshots";
  std::error_code error;
  fs::remove_all(folder, error);  // an earlier post's snapshots, at other times (--force)
  const SnapshotFiles files =
      draw_snapshots(folder, snapshots, input.material_names, settings.stage);
  for (const fs::path& file : files.files) out.record(file);
  for (const Snapshot& s : snapshots) result.snapshot_times.push_back(s.time);
  result.snapshots = files.pictures;
  return files.plotted;
}

}  // namespace

double case_gravity(const fs::path& case_folder) {
  constexpr double kStandardGravity = 9.81;
  const fs::path stages = case_folder / "stages.toml";
  if (!fs::exists(stages)) return kStandardGravity;
  TomlDocument document(stages);
  TomlTable root = document.root();
  if (!root.has("gravity")) return kStandardGravity;
  double squared = 0;
  for (double component : root.numbers("gravity")) squared += component * component;
  if (!(squared > 0)) root.fail("the leading wave needs gravity, but 'gravity' is zero", "gravity");
  return std::sqrt(squared);
}

PostResult postprocess(const fs::path& case_folder, const fs::path& post_folder, bool overwrite) {
  // Everything the user wrote is checked before the post folder is touched, so a typo never
  // leaves an empty or half-written post folder behind.
  const PostSettings settings = read_post_settings(case_folder / "post.toml");
  std::optional<SlideInput> slide;
  if (settings.measures_slide()) slide = read_slide_input(settings, case_folder);
  const int dimension = case_dimension(case_folder);
  std::optional<WaterInput> water;
  if (settings.measures_water()) water = read_water_input(settings, case_folder, dimension);
  const std::optional<SnapshotInput> snapshot_input =
      read_snapshot_input(settings, case_folder, slide, water);

  prepare_output_folder(post_folder, overwrite);

  PostResult result;
  PostFolder out(post_folder, result);
  bool plotted = true;
  if (slide) plotted = measure_slide(settings, *slide, case_folder, dimension, out, result);
  if (water) plotted = measure_water(settings, *water, dimension, out, result) && plotted;
  if (!result.errors.empty()) write_errors(result.errors, out);
  if (snapshot_input)
    plotted = draw_scene_snapshots(settings, *snapshot_input, dimension, out, result) && plotted;
  plotted = plot_time_histories(case_folder, out) && plotted;
  result.plots_written = plotted;
  return result;
}

PostResult plot_run_histories(const fs::path& case_folder, const fs::path& post_folder,
                              bool overwrite) {
  PostResult result;
  const fs::path output = case_folder / "output";
  bool any = false;
  std::error_code error;
  if (fs::is_directory(output, error))
    for (const auto& entry : fs::directory_iterator(output)) {
      const std::string name = entry.path().filename().string();
      any = any || name == "probes" ||
            (name.size() > 12 && name.compare(name.size() - 12, 12, "_history.csv") == 0);
    }
  if (!any) return result;
  prepare_output_folder(post_folder, overwrite);
  PostFolder out(post_folder, result);
  result.plots_written = plot_time_histories(case_folder, out);
  return result;
}

}  // namespace lituya::post
