#pragma once
// `lituya post`: what a landslide run is judged by. From the solver's point output series it
// measures, at every output time, how far the front of the sliding mass has run down the
// slope, how thick the mass is along the slope, and how high it stands at the upstream wall;
// from the liquid (water) point series, the surface elevation at wave gauges and the height
// and position of the leading wave. It writes them as CSV tables and PNG plots next to the
// reference data of the case.
//
// Slide measurements are made in the slope frame (along-slope distance s, height t above the
// slope surface), because that is how the laboratory flumes report runout and thickness.
// Water measurements are made in the global frame (x along the flume, y vertical), because
// that is how wave gauges are placed and read.
#include <array>
#include <cmath>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "lituya/common/toml_reader.hpp"
#include "lituya/post/reference_error.hpp"

namespace lituya::post {

// post.toml, validated (format "lituya-post" version 1; see manuals/file-formats.md).
struct PostSettings {
  // Slide measures (runout, wall height, thickness profiles): taken when track_materials
  // names at least one material, skipped otherwise (a water-only case).
  std::array<double, 3> slope_origin{};  // a point on the slope surface, s = t = 0
  double slope_angle_deg = 0;            // the slope descends towards +x
  std::vector<std::string> track_materials;
  std::optional<double> initial_front;  // s of the front at t = 0; absent: first output's
  double wall_position = 0;             // s of the upstream wall
  double bin_width = 0.01;              // along-slope bin for front and thickness
  int min_points = 2;                   // points a bin needs to count as part of the mass
  std::vector<double> profile_times;    // s
  std::string stage = "release";        // the output series to read
  std::string reference_file;           // absolute, or empty when none is given

  // Water surface measures: taken when there are gauges or leading_wave is true.
  std::vector<double> gauges;              // x of the wave gauges (vertical lines), m
  std::vector<std::string> gauge_names;    // one per gauge; default "x=<position>"
  double still_water_level = NAN;          // m, y of the still water surface
  std::optional<double> gauge_half_width;  // m; absent: the median point spacing
  bool leading_wave = false;               // track the first wave crest
  double leading_wave_start = 0;           // m, x from which the crest is looked for
  double leading_wave_min_height = 0.002;  // m, smallest crest that counts as a wave
  // Liquid points whose porosity is below this are pore water (of a saturated slide, or
  // water that entered a dry one) and are not part of the free surface that the gauges, the
  // leading wave and the surface profiles measure. 0 counts every liquid point.
  double surface_min_porosity = 0.9;
  std::string liquid_stage;          // the liquid series read; default = stage
  std::string gauge_reference_file;  // absolute, or empty when none is given

  bool measures_slide() const { return !track_materials.empty(); }
  bool measures_water() const { return !gauges.empty() || leading_wave; }

  // Where the settings came from, so that errors found later (a material name that
  // materials.toml does not know, a stage that was never written) point at the right line.
  std::string file;
  int track_materials_line = 0;
  int stage_line = 0;
  int water_line = 0;  // the line that asked for the water measures (gauges, leading_wave
                       // or liquid_stage), where a missing liquid series is reported
};
PostSettings read_post_settings(const std::filesystem::path& post_toml);
// The same checks on a table already open: `lituya pre` runs them on the scene's [post], so
// that a key post would refuse is an error at the scene's line before anything is solved.
// Data files are resolved against `file`'s folder.
PostSettings read_post_table(const TomlTable& root, const std::filesystem::path& file);

// Material names in id order (id = position in the [[material]] list of materials.toml).
std::vector<std::string> read_material_names(const std::filesystem::path& materials_toml);

// tracked[id] is true for the materials named in settings.track_materials. A name that is not
// in `material_names` is an InputError at the track_materials line of post.toml.
std::vector<bool> tracked_material_mask(const PostSettings& settings,
                                        const std::vector<std::string>& material_names);

// One entry of a .pvd collection; `file` is resolved against the .pvd's folder.
struct SeriesEntry {
  double time;
  std::filesystem::path file;
};
// Entries sorted by time (stable). InputError on a missing or garbled file.
std::vector<SeriesEntry> read_pvd(const std::filesystem::path& pvd);

// The material points of one output. Optional arrays are empty when the file lacks them.
struct PointCloud {
  std::vector<Eigen::Vector3d> position;
  std::vector<int> material;   // id in materials.toml
  std::vector<double> volume;  // m3 (m2 per metre in 2D)
  std::vector<double> mass;    // kg (kg per metre in 2D), when written
  std::vector<int> id;         // index of the point in the case's points.vtu
  // Liquid points only (read_liquid_points): porosity n of the mixture the point is water
  // of, 1 for free water; its `volume` is the water volume, n times the mixture volume.
  std::vector<double> porosity;
  std::vector<double> speed;  // m/s, |velocity| (of the soil or of the water), when written
  int dimension = 2;          // 2: plane strain (z = 0), 3: flume with width along z
};
// `dimension` 0 infers it: 2 when every z is 0, else 3. InputError on a missing or garbled
// file.
PointCloud read_points(const std::filesystem::path& vtu, int dimension = 0);
// The liquid (water) points of one output, <stage>_liquid_NNNN.vtu: as read_points, with
// `porosity` when present, and an InputError naming the file when it has no `volume`, which
// the free surface needs.
PointCloud read_liquid_points(const std::filesystem::path& vtu, int dimension = 0);

// A point stands for a cell-sized piece of material: its spacing is sqrt(V) in 2D and
// cbrt(V) in 3D, 0 when the volume is unknown or not positive. V is the volume, or for a
// liquid point with a porosity n in (0, 1) (pore water of saturated soil) volume / n, the
// mixture volume the point was seeded for.
double point_spacing(const PointCloud& points, size_t i);
// Median of point_spacing over the points with a positive volume; NaN when there are none.
double median_point_spacing(const PointCloud& points);

// Slope frame: s = along-slope distance from the origin (downslope positive; the slope
// descends towards +x at `slope_angle_deg`), t = distance normal to the slope (positive into
// the air). z (flume width in 3D) is ignored.
class SlopeFrame {
 public:
  SlopeFrame(const Eigen::Vector3d& origin, double slope_angle_deg);
  double s(const Eigen::Vector3d& p) const;
  double t(const Eigen::Vector3d& p) const;
  // Global position of slope coordinates (s, t) at width z: the inverse of s() and t().
  Eigen::Vector3d point(double s, double t, double z = 0) const;

 private:
  Eigen::Vector3d origin_;
  Eigen::Vector3d downslope_;     // unit, along the slope
  Eigen::Vector3d slope_normal_;  // unit, out of the slope into the air
};

// Bins are [k w, (k+1) w) in s, aligned on the slope origin so that the same bin is the same
// stretch of slope at every output time.
//
// The front: starting at the most upslope bin holding >= min_points tracked points, walk
// downslope while every bin holds >= min_points; the front is the downslope edge of the last
// such bin. A few points thrown ahead of the mass therefore do not count as runout. NaN when
// no bin qualifies.
double front_position(const PointCloud& points, const std::vector<bool>& tracked_material,
                      const SlopeFrame& frame, double bin_width, int min_points);

// The front of the tracked mass: the smallest s below which `share` (e.g. 0.99) of the tracked
// points' mass lies. Unlike front_position it weighs each point by its mass, so a few grains
// thrown ahead, or a layer thinner than the bins' point count, move it by their mass only: it
// converges with the cell size where front_position, which follows the thinnest layer a bin
// still counts, does not (verification/column_collapse). NaN without masses or tracked points.
double mass_front_position(const PointCloud& points, const std::vector<bool>& tracked_material,
                           const SlopeFrame& frame, double share);

// Thickness of one bin: s is the bin centre.
struct ProfileBin {
  double s, thickness;
};
// For every bin from the most upslope to the most downslope tracked point, and one empty
// bin beyond each (so that a plotted profile closes on the slope surface): the largest
// t + half point spacing of its tracked points (spacing = sqrt(volume) in 2D, cbrt(volume)
// in 3D, 0 when the volumes are unknown), i.e. the top of the mass above the slope surface.
// Bins with fewer than min_points tracked points have thickness 0.
std::vector<ProfileBin> thickness_profile(const PointCloud& points,
                                          const std::vector<bool>& tracked_material,
                                          const SlopeFrame& frame, double bin_width,
                                          int min_points);

// Thickness of the mass in the bin [wall_position, wall_position + bin_width) just downslope
// of the upstream wall, as thickness_profile measures it; 0 with fewer than min_points points.
double wall_height(const PointCloud& points, const std::vector<bool>& tracked_material,
                   const SlopeFrame& frame, double wall_position, double bin_width, int min_points);

// The reference CSV of a case: columns time,front_travel,wall_height (a header naming them
// in any order, or no header and this order); a blank field means no value.
struct ReferenceData {
  std::vector<double> time;
  std::vector<std::optional<double>> front_travel, wall_height;
};
ReferenceData read_reference(const std::filesystem::path& csv);

// The reference CSV of the wave gauges: a header line `time,<gauge name>...` (any order, any
// subset of the gauges), then rows; a blank field means no value. value[g][row] belongs to
// gauge g of `gauge_names`. A column that names no gauge is an InputError at the header.
struct GaugeReference {
  std::vector<double> time;
  std::vector<std::vector<std::optional<double>>> value;
};
GaugeReference read_gauge_reference(const std::filesystem::path& csv,
                                    const std::vector<std::string>& gauge_names);

// Free surface at a wave gauge, minus still_water_level, read over the column of the liquid
// points whose x lies within half_width of gauge_x (in 3D at any z). Each point stands for a
// square (cube) of its spacing (see point_spacing), filled with water at volume / spacing^d,
// and counts with the share of its width inside the column. The surface is the highest level
// at which the column is three quarters full (of 1, or of its fullest level when it holds
// only pore water or spray), raised by the water above that level spread over the column.
// So still water made of whole points reads exactly 0, a point standing above its neighbours
// lifts the surface by its share of the column and a drop of spray by its volume, not by
// their height. Points without a volume count with their centre only. NaN when no liquid
// point is in that column.
double gauge_elevation(const PointCloud& liquid, double gauge_x, double half_width,
                       double still_water_level);

// One bin of a free-surface profile: x is the bin centre, eta the elevation of the surface
// above still water (as gauge_elevation measures it over the bin), NaN when the bin holds no
// liquid point.
struct SurfaceBin {
  double x, eta;
};
// Bins [origin + k w, origin + (k + 1) w) from the most upstream to the most downstream
// liquid point, empty ones included (so that neighbours in the list are neighbours in x).
// A point flung absurdly far would make that list huge; then only occupied bins are listed.
std::vector<SurfaceBin> surface_profile(const PointCloud& liquid, double origin, double bin_width,
                                        double still_water_level);

// The leading (first) wave of a surface profile, the crest that has travelled furthest
// downstream (+x, away from the slide), as the paper's Fig. 19 follows it. Among the bins
// whose centre lies at or beyond `from_x`:
//   max_eta   = the highest eta;
//   threshold = max(min_height, 0.1 max_eta);
//   a crest is a bin with eta > threshold that is at least as high as every non-empty bin
//   within 2 bins on either side (bins outside `from_x` included), so a one-bin bump on the
//   flank of a wave, or ripples below the threshold, are not taken for a wave;
//   the leading crest is the most downstream crest.
// All NaN when no bin holds liquid; crest_x and crest_eta NaN when no bin is a crest.
// This is the rule for one frame on its own; a record over time is made by
// track_leading_wave, which starts with it.
struct LeadingWave {
  double crest_x = NAN, crest_eta = NAN, max_eta = NAN;
};
LeadingWave find_leading_wave(const std::vector<SurfaceBin>& profile, double from_x,
                              double min_height);

// The leading wave followed from frame to frame: one LeadingWave per profile, profiles[k]
// being the surface profile (surface_profile) of the liquid output at time[k] (increasing).
// Picked frame by frame, the most downstream crest jumps between the wave and a precursor
// ripple ahead of it that crosses the threshold in some frames only; a crest, however, cannot
// be further from where it was than a long wave can run in the meantime. So:
//   - the track starts at the first frame in which find_leading_wave finds a crest, with
//     that crest (the most downstream one);
//   - in every later frame the wave is looked for only within reach of the last position
//     taken, x_last at t_last: the bins beyond from_x with |x - x_last| <= c_max (t - t_last)
//     + one bin (a position is known to a bin), c_max = kLeadingWaveSpeedMargin
//     sqrt(g (d + eta_max)), d = still_water_depth, g = gravity and eta_max the highest
//     surface beyond from_x in the frame of x_last and in this one. The bound holds both
//     ways, since a wave reflected from the end wall runs back at the same speed;
//   - the highest bin of that window above min_height is the leading wave (on a tie, the
//     most downstream), and the track moves there. The threshold relative to the highest
//     surface is dropped: the window already keeps distant ripples and the splash out.
//     Highest, not nearest a predicted position: a slide-generated crest is nonlinear,
//     steepens and breaks, and runs well off any sqrt(g (d + eta)) prediction (in Case C at
//     0.6 of it while the slide pushes it), whereas a ripple that happens to sit near the
//     prediction is lower than the wave by what makes it a ripple. Inside the window the
//     highest bin is a crest by find_leading_wave's test; on the window's edge it need not
//     be (higher water just beyond). It is taken all the same: the crest then lies further
//     on, typically a broad crest whose highest bin the surface's noise had put at its rear,
//     and the track climbs towards it at no more than c_max. Holding on to crests only would
//     leave the track on a noise bump behind a broad crest (on the full Case C run it read
//     20 mm 0.18 m behind a 33 mm crest at 0.74 s);
//   - no bin of the window above min_height (the wave broke, or ran out of the profile):
//     NaN, and the track stays at (x_last, t_last), so the next window grows with the time
//     since the wave was last seen.
// max_eta is, in every frame, the highest surface beyond from_x, as find_leading_wave has it.
// The bin width is the smallest spacing between neighbouring bins of the profile.
// time and profiles must have the same size (std::invalid_argument otherwise).
//
// kLeadingWaveSpeedMargin = 1.5 is a bound, not a fit. No long wave outruns sqrt(g (d + eta)) by
// much: a bore of height eta <= d runs at sqrt(g (d + eta)) sqrt(1 + eta / (2 d)), at most 1.22
// times it; the rest is room for the top of a steepening crest, which runs ahead of its wave before
// it breaks. A depth that is NaN or negative counts as 0; gravity must be > 0
// (std::invalid_argument).
constexpr double kLeadingWaveSpeedMargin = 1.5;
std::vector<LeadingWave> track_leading_wave(const std::vector<double>& time,
                                            const std::vector<std::vector<SurfaceBin>>& profiles,
                                            double from_x, double min_height,
                                            double still_water_depth, double gravity = 9.81);

// |gravity| (m/s2) of case_folder/stages.toml, which bounds how fast the leading wave can run;
// 9.81 when the case does not state it (an older case folder). InputError when it is zero.
double case_gravity(const std::filesystem::path& case_folder);

// The deepest still water of a liquid output: still_water_level minus the lowest bottom of a
// point (centre - half spacing, see point_spacing). Read on the lake at rest (the first
// output), it bounds the long-wave speed for track_leading_wave. NaN without liquid points.
double still_water_depth(const PointCloud& liquid, double still_water_level);

// The crest of the first wave of a gauge record eta(t), by the zero up-crossing definition of
// a wave: the wave starts at the first sample above `onset` (m above still water; ripples of
// still water stay below it) and lasts until the record next falls below still water
// (eta < 0); its crest is its highest sample. The time is refined by a parabola through that
// sample and its two neighbours (by at most half a sample). Samples with NaN eta (no water at
// the gauge) are left out. `complete` is false when the record ends before the wave does (its
// crest may be still to come). time and height NaN when no sample exceeds `onset`.
// A wiggle on the rising flank, or a dip of the crest's plateau, is inside the wave and
// changes nothing: a "first local maximum" would stop on it.
// `area` is the integral of eta over the whole first wave, from the record's last rise through
// still water before the onset to its next fall below it (both crossings interpolated between
// samples; trapezoids in between), in m s. Times the wave's celerity it is the wave's volume
// per unit width. The crest of a steep, noisy front is one sample of it; the area sums every
// sample, and converges where the crest does not (user manual, section 3, Case B).
struct WaveCrest {
  double time = NAN, height = NAN;
  double area = NAN;  // m s
  bool complete = false;
};
WaveCrest first_wave_crest(const std::vector<double>& time, const std::vector<double>& eta,
                           double onset);

struct TimedProfile {
  double requested_time;  // from profile_times
  double time;            // of the output closest to it
  std::vector<ProfileBin> bins;
};

struct TimedSurface {
  double requested_time;  // from profile_times
  double time;            // of the liquid output closest to it
  std::vector<SurfaceBin> bins;
};

struct PostResult {
  // Slide measures; empty when track_materials is absent.
  std::vector<double> time, front_position, front_travel, wall_height;
  // The front of 99 % of the tracked mass (mass_front_position), and its travel from where it
  // stood at the first output; NaN where the points carry no mass field.
  std::vector<double> mass_front_position, mass_front_travel;
  std::vector<TimedProfile> profiles;

  // Water measures, one value per liquid output; empty when no gauges and no leading wave
  // were asked for. NaN marks "no value" (no water at the gauge, no wave crest).
  std::vector<double> liquid_time;
  std::vector<std::string> gauge_names;
  std::vector<std::vector<double>> gauge_eta;       // [gauge][output], m above still water
  double gauge_half_width = NAN;                    // m, as given or inferred from the volumes
  std::vector<double> crest_x, crest_eta, max_eta;  // leading wave (when asked for)
  std::vector<TimedSurface> surface_profiles;

  // One entry per series drawn against a reference (runout, wall height, each gauge with
  // reference data), as written to errors.csv.
  std::vector<ReferenceError> errors;
  // The snapshots (snapshot.hpp): the output times drawn, and the PNGs made.
  std::vector<double> snapshot_times;
  std::vector<std::filesystem::path> snapshots;

  std::vector<std::filesystem::path> files;  // everything written into the post folder
  bool plots_written = false;                // false when gnuplot is missing or failed
};
// Reads case_folder/post.toml and what it asks for: materials.toml, stages.toml (dimension),
// output/<stage>_points.pvd (slide measures) and output/<liquid_stage>_liquid.pvd (water
// measures). Writes into post_folder (refused if it holds files, unless `overwrite`):
//   slide: runout.csv, wall_height.csv, profiles.csv, reference copies, and runout.png,
//          wall_height.png, profiles.png;
//   water: gauges.csv, gauges.png and the gauge reference copies (with gauges),
//          leading_wave.csv, leading_wave.png (with leading_wave), surface_profiles.csv,
//          surface_profiles.png;
//   against reference data: errors.csv (reference_error.hpp), the errors also in the titles;
//   with profile_times: snapshots/ (snapshot.hpp), the scene by material and by speed;
//   always: the plots of plot_run_histories();
// each PNG with its .gp script. Everything is validated before the folder is touched.
PostResult postprocess(const std::filesystem::path& case_folder,
                       const std::filesystem::path& post_folder, bool overwrite);

// Plots the run's probe tables (output/probes/<name>.csv: probe_<name>_<field>.png against the
// run time) and stage histories (output/<stage>_history.csv: <stage>_history_kinetic_energy.png,
// _time_step.png, _max_speed.png against the stage time, and <stage>_history_wall_<name>.png
// with the forces on each held boundary) into post_folder (refused if it holds
// files, unless `overwrite`). postprocess() draws them too; this serves a case without
// post.toml. The result lists the files; nothing is written when the run wrote no such table.
PostResult plot_run_histories(const std::filesystem::path& case_folder,
                              const std::filesystem::path& post_folder, bool overwrite);

}  // namespace lituya::post
