#pragma once
// Snapshots of the scene: the material points of one output time drawn to scale, coloured by
// material (the soil materials and the water told apart, named as in materials.toml) and by
// speed (|velocity| in m/s, with a colour bar). Each point is a filled disc around its square
// cell (radius = spacing / sqrt(2), spacing as in point_spacing), so a mass of points reads as
// a solid body without holes; the axes are scaled equally.
//
// A 3D case is drawn as a side view: the points projected on the x-y plane (x along the
// flume, y up), seen from +z, the nearer points (larger z) drawn over the farther ones.
//
// Files, in <post>/snapshots/, per time (named t<time with 3 decimals> e.g. t0.230, more
// decimals when two times would share a name):
//   t0.230.csv           phase,material,x,y,z,radius,speed: the points drawn, water first;
//                        phase 0 = soil point, 1 = liquid point; speed blank when the output
//                        has no velocity;
//   t0.230_material.png  (+ .gp) the points coloured by material;
//   t0.230_speed.png     (+ .gp) coloured by speed, on one colour scale for all times.
// All snapshots share the same axes, so a series of them can be flipped through.
#include <filesystem>
#include <string>
#include <vector>

#include "lituya/post/postprocess.hpp"

namespace lituya::post {

struct SnapshotPoint {
  int phase = 0;  // 0 soil (solid point), 1 water (liquid point)
  int material = 0;
  double x = 0, y = 0, z = 0;
  double radius = 0;  // m, of the disc drawn: point spacing / sqrt(2)
  double speed = 0;   // m/s; NaN when the output has no velocity
};

struct Snapshot {
  double requested_time = 0;          // from profile_times
  double time = 0;                    // of the output drawn
  std::vector<SnapshotPoint> points;  // liquid points first, then solid points
};

// The points of one output time; either cloud may be null (a dry case, or no solid series).
Snapshot make_snapshot(double requested_time, double time, const PointCloud* solid,
                       const PointCloud* liquid);

// The name of a snapshot's files: "t" and the time with 3 decimals, e.g. "t0.230".
std::string snapshot_name(double time, int decimals = 3);

struct SnapshotFiles {
  std::vector<std::filesystem::path> files;     // CSV tables and scripts, and PNGs made
  std::vector<std::filesystem::path> pictures;  // the PNGs made, material then speed per time
  bool plotted = true;                          // false when a PNG could not be made
};

// Writes the snapshots into `folder` (created if needed) as described above. `material_names`
// names the material ids (id = index; an id beyond it is drawn as "material <id>"); `stage`
// is named in the titles.
SnapshotFiles draw_snapshots(const std::filesystem::path& folder,
                             const std::vector<Snapshot>& snapshots,
                             const std::vector<std::string>& material_names,
                             const std::string& stage);

}  // namespace lituya::post
