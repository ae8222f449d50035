// `lituya post`: runs the measurements over the whole output series of one stage and writes
// the tables and plots a user compares with the laboratory.
#include "lituya/post/postprocess.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <set>

#include "lituya/common/input_error.hpp"
#include "lituya/common/output_folder.hpp"
#include "lituya/common/toml_reader.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::post {

namespace fs = std::filesystem;

namespace {

// A blank field is "no value" (the same convention as the reference CSV), so a time at which
// no front could be found plots as a gap rather than as a misleading number.
std::string csv_number(double v) {
  if (!std::isfinite(v)) return "";
  char text[32];
  std::snprintf(text, sizeof text, "%.10g", v);
  return text;
}

class CsvFile {
 public:
  CsvFile(const fs::path& file, const std::string& header) : file_(file), out_(file) {
    if (!out_) throw std::runtime_error("cannot write " + file.string());
    out_ << header << "\n";
  }
  template <typename... Values>
  void row(const Values&... values) {
    bool first = true;
    ((out_ << (first ? "" : ",") << csv_number(values), first = false), ...);
    out_ << "\n";
  }
  void close() {
    out_.close();
    if (!out_) throw std::runtime_error("error while writing " + file_.string());
  }

 private:
  fs::path file_;
  std::ofstream out_;
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

}  // namespace

PostResult postprocess(const fs::path& case_folder, const fs::path& post_folder, bool overwrite) {
  // Everything the user wrote is checked before the post folder is touched, so a typo never
  // leaves an empty or half-written post folder behind.
  const PostSettings settings = read_post_settings(case_folder / "post.toml");
  const std::vector<std::string> material_names =
      read_material_names(case_folder / "materials.toml");
  const std::vector<bool> tracked = tracked_material_mask(settings, material_names);
  const int dimension = case_dimension(case_folder);
  const SlopeFrame frame(
      Eigen::Vector3d(settings.slope_origin[0], settings.slope_origin[1], settings.slope_origin[2]),
      settings.slope_angle_deg);

  const fs::path pvd = case_folder / "output" / (settings.stage + "_points.pvd");
  if (!fs::exists(pvd))
    throw InputError(settings.file, settings.stage_line,
                     "no output series for stage '" + settings.stage + "': " + pvd.string() +
                         " does not exist (run `lituya solve` first, or check the stage name)");
  const std::vector<SeriesEntry> series = read_pvd(pvd);
  if (series.empty()) throw InputError(pvd.string(), 0, "the collection lists no outputs");
  std::optional<ReferenceData> reference;
  if (!settings.reference_file.empty()) reference = read_reference(settings.reference_file);

  prepare_output_folder(post_folder, overwrite);

  PostResult result;
  std::vector<size_t> profile_output;
  for (double t : settings.profile_times) {
    profile_output.push_back(closest_output(series, t));
    result.profiles.push_back({t, series[profile_output.back()].time, {}});
  }

  std::optional<std::vector<double>> initial_volume;
  for (size_t k = 0; k < series.size(); ++k) {
    PointCloud cloud = read_points(series[k].file, dimension);
    fill_missing_volumes(cloud, case_folder, initial_volume);
    if (cloud.material.empty() && material_names.size() > 1)
      throw InputError(series[k].file.string(), 0,
                       "the points have no 'material' field, so the tracked materials cannot be "
                       "told apart (add \"material\" to [output] point_fields)");
    result.time.push_back(series[k].time);
    result.front_position.push_back(
        front_position(cloud, tracked, frame, settings.bin_width, settings.min_points));
    result.wall_height.push_back(wall_height(cloud, tracked, frame, settings.wall_position,
                                             settings.bin_width, settings.min_points));
    for (size_t p = 0; p < profile_output.size(); ++p)
      if (profile_output[p] == k)
        result.profiles[p].bins =
            thickness_profile(cloud, tracked, frame, settings.bin_width, settings.min_points);
  }
  const double start_front = settings.initial_front.value_or(result.front_position.front());
  for (double front : result.front_position) result.front_travel.push_back(front - start_front);

  // Tables.
  const fs::path runout_csv = post_folder / "runout.csv";
  const fs::path wall_csv = post_folder / "wall_height.csv";
  const fs::path profiles_csv = post_folder / "profiles.csv";
  {
    CsvFile runout(runout_csv, "time,front_position,front_travel");
    CsvFile wall(wall_csv, "time,wall_height");
    for (size_t k = 0; k < result.time.size(); ++k) {
      runout.row(result.time[k], result.front_position[k], result.front_travel[k]);
      wall.row(result.time[k], result.wall_height[k]);
    }
    runout.close();
    wall.close();
  }
  // Two requested times may fall on the same output: its profile is written once.
  std::vector<double> profile_times_written;
  {
    CsvFile profiles(profiles_csv, "time,s,thickness");
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
  if (reference) {
    const fs::path copy = post_folder / "reference.csv";
    std::error_code same;
    if (!fs::equivalent(settings.reference_file, copy, same))
      fs::copy_file(settings.reference_file, copy, fs::copy_options::overwrite_existing);
    reference_runout_csv = post_folder / "reference_runout.csv";
    reference_wall_csv = post_folder / "reference_wall_height.csv";
    CsvFile runout(reference_runout_csv, "time,front_travel");
    CsvFile wall(reference_wall_csv, "time,wall_height");
    for (size_t k = 0; k < reference->time.size(); ++k) {
      if (reference->front_travel[k]) runout.row(reference->time[k], *reference->front_travel[k]);
      if (reference->wall_height[k]) wall.row(reference->time[k], *reference->wall_height[k]);
    }
    runout.close();
    wall.close();
  }

  // Plots.
  const std::string stage = " (stage '" + settings.stage + "')";
  std::vector<PlotSeries> runout_series{{runout_csv, 1, 3, "Lituya (MPM)"}};
  std::vector<PlotSeries> wall_series{{wall_csv, 1, 2, "Lituya (MPM)"}};
  if (reference) {
    runout_series.push_back({reference_runout_csv, 1, 2, "reference", true});
    wall_series.push_back({reference_wall_csv, 1, 2, "reference", true});
  }
  std::vector<PlotSeries> profile_series;
  for (double t : profile_times_written) {
    char label[48];
    std::snprintf(label, sizeof label, "t = %g s", t);
    profile_series.push_back({profiles_csv, 2, 3, label, false, 1, t});
  }
  bool plotted = plot_xy(post_folder / "runout.png", "Front travel along the slope" + stage,
                         "time (s)", "front travel (m)", runout_series);
  plotted = plot_xy(post_folder / "wall_height.png", "Height of the mass at the wall" + stage,
                    "time (s)", "height normal to the slope (m)", wall_series, true) &&
            plotted;
  plotted = plot_xy(post_folder / "profiles.png", "Thickness along the slope" + stage,
                    "along-slope distance s (m)", "thickness normal to the slope (m)",
                    profile_series, true) &&
            plotted;
  result.plots_written = plotted;
  return result;
}

}  // namespace lituya::post
