// Snapshots of the scene at the profile times, by material and by speed (snapshot.hpp).
#include "lituya/post/snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

#include "lituya/common/csv_writer.hpp"
#include "lituya/post/plot.hpp"

namespace lituya::post {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Soil materials in earth colours, water in blues; both lists cycle for many materials.
// Neighbours in the list differ in lightness as well as hue (a slide on a grey bed).
constexpr const char* kSoilColours[] = {"#b8742a", "#7f7f7f", "#5b3a1e", "#d9b44a",
                                        "#5b8c3a", "#a83232", "#7d5fa8", "#3d3d3d"};
constexpr const char* kWaterColours[] = {"#3a86d4", "#8cc4f2", "#1d4f91"};

// Enough digits for a picture (a micrometre at metre scale) and a compact table.
std::string short_number(double v, int digits) {
  if (!std::isfinite(v)) return "";
  char text[40];
  std::snprintf(text, sizeof text, "%.*g", digits, v);
  return text;
}

// 1, 2, 2.5 or 5 times a power of ten, at or above v: a colour bar that ends on a round number.
double round_up(double v) {
  if (!(v > 0) || !std::isfinite(v)) return 1.0;
  const double decade = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0})
    if (m * decade >= v * (1 - 1e-12)) return m * decade;
  return 10 * decade;
}

// The disc around the point's square (the face of its cube in 3D): radius spacing / sqrt(2).
// Smaller discs leave holes between the points of a uniform mass (discs of the point's own
// area leave them at the middle of every triangle of points), and a picture of a solid body
// must not look like a sieve; the outline grows by at most 0.21 spacing.
const double kDiscRadius = 1 / std::numbers::sqrt2;

void add_cloud(Snapshot& snapshot, const PointCloud& cloud, int phase) {
  const double fallback = kDiscRadius * median_point_spacing(cloud);
  std::vector<SnapshotPoint> points;
  points.reserve(cloud.position.size());
  for (size_t i = 0; i < cloud.position.size(); ++i) {
    SnapshotPoint p;
    p.phase = phase;
    p.material = cloud.material.empty() ? (phase == 1 ? -1 : 0) : cloud.material[i];
    p.x = cloud.position[i].x();
    p.y = cloud.position[i].y();
    p.z = cloud.position[i].z();
    p.radius = kDiscRadius * point_spacing(cloud, i);
    if (!(p.radius > 0)) p.radius = std::isfinite(fallback) ? fallback : 0.0;
    p.speed = cloud.speed.empty() ? kNaN : cloud.speed[i];
    points.push_back(p);
  }
  // Seen from +z: the farther points first, so the nearer ones are drawn over them.
  std::stable_sort(points.begin(), points.end(),
                   [](const SnapshotPoint& a, const SnapshotPoint& b) { return a.z < b.z; });
  snapshot.points.insert(snapshot.points.end(), points.begin(), points.end());
}

struct Frame {
  double x0, x1, y0, y1;
};

// One frame for every snapshot, around every point's disc, with a small margin.
Frame common_frame(const std::vector<Snapshot>& snapshots, double default_radius) {
  Frame f{INFINITY, -INFINITY, INFINITY, -INFINITY};
  for (const Snapshot& s : snapshots)
    for (const SnapshotPoint& p : s.points) {
      const double r = p.radius > 0 ? p.radius : default_radius;
      f.x0 = std::min(f.x0, p.x - r);
      f.x1 = std::max(f.x1, p.x + r);
      f.y0 = std::min(f.y0, p.y - r);
      f.y1 = std::max(f.y1, p.y + r);
    }
  if (!(f.x0 < f.x1)) f = {f.x0 - 0.5, f.x0 + 0.5, f.y0, f.y1};
  if (!(f.y0 < f.y1)) f = {f.x0, f.x1, f.y0 - 0.5, f.y0 + 0.5};
  if (!std::isfinite(f.x0) || !std::isfinite(f.y0)) return {0, 1, 0, 1};
  const double margin = 0.02 * std::max(f.x1 - f.x0, f.y1 - f.y0);
  return {f.x0 - margin, f.x1 + margin, f.y0 - margin, f.y1 + margin};
}

std::string time_text(double t) {
  char text[40];
  std::snprintf(text, sizeof text, "%g", t);
  return text;
}

// The lines every snapshot script starts with: terminal, frame and labels.
std::string script_head(const std::string& png, const std::string& title, const Frame& f,
                        bool colour_bar) {
  // The canvas takes the frame's shape, so the equal scaling fills it rather than leaving a
  // wide blank band; a very tall or flat scene is bounded and gnuplot shrinks it to fit.
  const int width = 1200;
  const double plot_width = width - (colour_bar ? 260.0 : 160.0);
  const double aspect = (f.y1 - f.y0) / (f.x1 - f.x0);
  const int height = static_cast<int>(std::clamp(aspect * plot_width + 170.0, 320.0, 1500.0));
  std::ostringstream gp;
  gp << "# Written by `lituya post`; edit and re-run in this folder: gnuplot "
     << fs::path(png).replace_extension(".gp").string() << "\n"
     << "set terminal pngcairo size " << width << "," << height << " noenhanced\n"
     << "set output " << gnuplot_text(png) << "\n"
     << "set datafile separator ','\n"
     << "set title " << gnuplot_text(title) << "\n"
     << "set xlabel 'x (m)'\n"
     << "set ylabel 'y (m)'\n"
     << "set size ratio -1\n"
     << "set xrange [" << short_number(f.x0, 8) << ":" << short_number(f.x1, 8) << "]\n"
     << "set yrange [" << short_number(f.y0, 8) << ":" << short_number(f.y1, 8) << "]\n"
     << "set grid front lc rgb '#d0d0d0'\n"
     << "set style fill solid 1.0 noborder\n"
     << "set key below horizontal\n";
  return gp.str();
}

}  // namespace

Snapshot make_snapshot(double requested_time, double time, const PointCloud* solid,
                       const PointCloud* liquid) {
  Snapshot snapshot;
  snapshot.requested_time = requested_time;
  snapshot.time = time;
  if (liquid) add_cloud(snapshot, *liquid, 1);
  if (solid) add_cloud(snapshot, *solid, 0);
  return snapshot;
}

std::string snapshot_name(double time, int decimals) {
  char text[48];
  std::snprintf(text, sizeof text, "t%.*f", decimals, time);
  return text;
}

SnapshotFiles draw_snapshots(const fs::path& folder, const std::vector<Snapshot>& snapshots,
                             const std::vector<std::string>& material_names,
                             const std::string& stage) {
  SnapshotFiles result;
  if (snapshots.empty()) return result;
  fs::create_directories(folder);

  // Names: 3 decimals unless two different times would share one.
  std::vector<std::string> names;
  for (int decimals = 3; decimals <= 9; decimals += 3) {
    names.clear();
    std::set<std::string> seen;
    bool unique = true;
    for (const Snapshot& s : snapshots) {
      names.push_back(snapshot_name(s.time, decimals));
      unique = seen.insert(names.back()).second && unique;
    }
    if (unique) break;
  }
  for (size_t k = 0; k < names.size(); ++k)
    if (std::count(names.begin(), names.begin() + k, names[k]) > 0)
      names[k].append(1, '_').append(std::to_string(k + 1));

  // Materials in drawing order: those of the water first (drawn under the soil, which hides
  // the pore water of a saturated mass), each with its colour and name.
  std::map<int, int> water_materials, soil_materials;  // id -> colour index
  double max_speed = 0, extent = 0;
  for (const Snapshot& s : snapshots)
    for (const SnapshotPoint& p : s.points) {
      auto& set = p.phase == 1 ? water_materials : soil_materials;
      set.emplace(p.material, 0);
      if (std::isfinite(p.speed)) max_speed = std::max(max_speed, p.speed);
      extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
    }
  int colour = 0;
  for (auto& [id, c] : water_materials) c = colour++;
  colour = 0;
  for (auto& [id, c] : soil_materials) c = colour++;
  auto material_name = [&](int id, int phase) {
    if (id >= 0 && id < static_cast<int>(material_names.size())) return material_names[id];
    if (id < 0) return std::string(phase == 1 ? "water" : "soil");
    return "material " + std::to_string(id);
  };

  // A point written without a volume gets a small disc, so that it still shows.
  const double default_radius = 0.002 * (extent > 0 ? extent : 1.0);
  const Frame frame = common_frame(snapshots, default_radius);
  const double speed_top = round_up(max_speed);
  const std::string stage_text = stage.empty() ? "" : " (stage '" + stage + "')";
  // Writes the script beside the picture and runs gnuplot on it.
  auto draw = [&](const std::string& png, const std::string& script) {
    result.files.push_back((folder / png).replace_extension(".gp"));
    const bool made = run_gnuplot_script(folder / png, script);
    if (made) {
      result.files.push_back(folder / png);
      result.pictures.push_back(folder / png);
    }
    result.plotted = made && result.plotted;
  };

  for (size_t k = 0; k < snapshots.size(); ++k) {
    const Snapshot& s = snapshots[k];
    const fs::path csv = folder / (names[k] + ".csv");
    CsvWriter table({"phase", "material", "x", "y", "z", "radius", "speed"});
    bool any_speed = false;
    for (const SnapshotPoint& p : s.points) {
      table.integer(p.phase).integer(p.material);
      table.text(short_number(p.x, 7)).text(short_number(p.y, 7)).text(short_number(p.z, 7));
      table.text(short_number(p.radius > 0 ? p.radius : default_radius, 4));
      table.text(short_number(p.speed, 4));
      table.end_row();
      any_speed = any_speed || std::isfinite(p.speed);
    }
    table.write(csv);
    result.files.push_back(csv);
    const std::string data = gnuplot_text(csv.filename().string());
    const std::string when = "t = " + time_text(s.time) + " s" + stage_text;

    // By material: one curve per material, so the legend names them.
    {
      const std::string png = names[k] + "_material.png";
      std::ostringstream gp;
      gp << script_head(png, "Points by material, " + when, frame, false);
      std::vector<std::string> curves;
      auto curve = [&](int id, int phase, const char* rgb) {
        std::ostringstream c;
        c << "  " << data << " skip 1 using (($1 == " << phase << " && $2 == " << id
          << ") ? $3 : NaN):4:6 with circles lc rgb '" << rgb << "' title "
          << gnuplot_text(material_name(id, phase));
        curves.push_back(c.str());
      };
      for (const auto& [id, c] : water_materials)
        curve(id, 1, kWaterColours[c % std::size(kWaterColours)]);
      for (const auto& [id, c] : soil_materials)
        curve(id, 0, kSoilColours[c % std::size(kSoilColours)]);
      if (curves.empty()) {
        gp << "set label 1 'no points' at graph 0.5, graph 0.5 center\n"
           << "plot NaN notitle\n";
      } else {
        gp << "plot \\\n";
        for (size_t i = 0; i < curves.size(); ++i)
          gp << curves[i] << (i + 1 < curves.size() ? ", \\\n" : "\n");
      }
      draw(png, gp.str());
    }

    // By speed: one colour scale (0 to the largest speed of all snapshots, rounded up).
    {
      const std::string png = names[k] + "_speed.png";
      std::ostringstream gp;
      gp << script_head(png, "Point speed, " + when, frame, true)
         << "set cblabel 'speed |v| (m/s)'\n"
         << "set cbrange [0:" << short_number(speed_top, 6)
         << "]\n"
         // Perceptually even (viridis-like): dark slow points, bright fast ones.
         << "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', "
            "4 '#fde725')\n";
      if (!any_speed) {
        gp << "set label 1 'the output has no velocity' at graph 0.5, graph 0.5 center\n"
           << "plot NaN notitle\n";
      } else {
        gp << "plot " << data << " skip 1 using 3:4:6:7 with circles lc palette notitle\n";
      }
      draw(png, gp.str());
    }
  }
  return result;
}

}  // namespace lituya::post
