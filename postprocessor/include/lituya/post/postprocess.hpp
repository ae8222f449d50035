#pragma once
// `lituya post`: what a landslide run is judged by. From the solver's point output series it
// measures, at every output time, how far the front of the sliding mass has run down the
// slope, how thick the mass is along the slope, and how high it stands at the upstream wall,
// and writes them as CSV tables and PNG plots next to the reference data of the case.
//
// Every measurement is made in the slope frame (along-slope distance s, height t above the
// slope surface), because that is how the laboratory flumes report runout and thickness.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace lituya::post {

// post.toml, validated (format "lituya-post" version 1; see manuals/file-formats.md).
struct PostSettings {
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

  // Where the settings came from, so that errors found later (a material name that
  // materials.toml does not know, a stage that was never written) point at the right line.
  std::string file;
  int track_materials_line = 0;
  int stage_line = 0;
};
PostSettings read_post_settings(const std::filesystem::path& post_toml);

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
  std::vector<int> id;         // index of the point in the case's points.vtu
  int dimension = 2;           // 2: plane strain (z = 0), 3: flume with width along z
};
// `dimension` 0 infers it: 2 when every z is 0, else 3. InputError on a missing or garbled
// file.
PointCloud read_points(const std::filesystem::path& vtu, int dimension = 0);

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

struct TimedProfile {
  double requested_time;  // from profile_times
  double time;            // of the output closest to it
  std::vector<ProfileBin> bins;
};

struct PostResult {
  std::vector<double> time, front_position, front_travel, wall_height;
  std::vector<TimedProfile> profiles;
  bool plots_written = false;  // false when gnuplot is missing or failed
};
// Reads case_folder/post.toml, materials.toml, stages.toml (dimension) and
// output/<stage>_points.pvd, and writes into post_folder (refused if it holds files, unless
// `overwrite`): runout.csv, wall_height.csv, profiles.csv, reference copies, and
// runout.png, wall_height.png, profiles.png with their .gp scripts.
PostResult postprocess(const std::filesystem::path& case_folder,
                       const std::filesystem::path& post_folder, bool overwrite);

}  // namespace lituya::post
