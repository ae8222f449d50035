// Seepage through a sand column under a falling head, against the Darcy-Forchheimer (Ergun)
// drag of eqs. (23), (24) (verification/seepage/README.md).
#include <cmath>

#include "case_support.hpp"
#include "lituya/post/plot.hpp"
#include "seepage_column.hpp"

namespace lituya::verify {

void run_seepage(const CaseContext& context, CaseResult& result) {
  const double sand_top = 0.5, plate = 0.2, width = 0.1, t1 = 0.3;  // seepage.geo
  // The scene's column (scene_*.toml): the water's reduced K_w, the sand's E and nu.
  SeepageColumn column;
  column.bulk_modulus = 2.15e5;
  column.constrained_modulus = SeepageColumn::constrained_modulus_of(1e7, 0.3);
  const auto case_folder = run_scene(context);
  const auto frames = read_series(case_folder, "seepage", "liquid");

  // The water of each frame as depths (volume over the width): the pond above the sand, the
  // pores of the sand, and the chamber below the plate. The pond's fall is the flux the case
  // checks; the chamber's rise is the flux through the column. They agree while the sand's
  // pores stay full; where they differ, the sand has gained or lost water (README, stop 32).
  struct Depths {
    double pond = 0, sand = 0, chamber = 0;
  };
  auto depths = [&](const Frame& f) {
    int c = 0;
    const auto volume = read_point_array(f.file, "volume", c);
    const auto x = read_positions(f.file);
    Depths d;
    for (std::size_t q = 0; q < volume.size(); ++q) {
      const double y = x[3 * q + 1];
      (y > sand_top ? d.pond : y >= plate ? d.sand : d.chamber) += volume[q] / width;
    }
    return d;
  };
  std::vector<Depths> at;
  for (const Frame& f : frames) at.push_back(depths(f));
  const Depths &first = at.front(), &last = at.back();
  // Drawn, not checked: the chamber also receives what the sand's bottom loses as it drains
  // (its pores under-fill at the outflow, where the water has no tension), so its rise is no
  // cleaner a measure of the flux than the pond's fall (README, stop 32).
  const double d0 = first.pond;
  std::vector<double> times;
  for (const Frame& f : frames) times.push_back(f.time);
  const auto reference = column.transient(d0, times);
  const std::vector<double> steady = column.steady_depth(d0, times);
  std::vector<std::vector<double>> rows;
  Depths at_t1{NAN, NAN, NAN};
  double reference_t1 = NAN;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    const Depths& d = at[k];
    rows.push_back({frames[k].time, d.pond, reference.pond_depth[k], steady[k], d.chamber,
                    reference.outflow[k], d.sand - first.sand});
    if (std::abs(frames[k].time - t1) < 1e-6) {
      at_t1 = d;
      reference_t1 = reference.pond_depth[k];
    }
  }
  // The references are the transient column's (README: the water the column's storage
  // releases as its pore pressure falls from hydrostatic keeps part of the pond).
  const double t_end = frames.back().time;
  const double reference_end = reference.pond_depth.back();
  const double reference_flux = (reference_t1 - reference_end) / (t_end - t1);
  add_check(result, "mean Darcy flux over 0.3 s to the end / Ergun value", "-",
            (at_t1.pond - last.pond) / (t_end - t1) / reference_flux, 1.0, 0.10);
  add_check(result, "pond depth at the end", "m", last.pond, reference_end,
            0.1 * (d0 - reference_end));

  const auto csv = context.work / "pond_depth.csv";
  write_csv(csv, "time,pond_depth,ergun,ergun_steady,chamber_depth,ergun_outflow,sand_water_change",
            rows);
  post::plot_xy(context.work / "pond_depth.png",
                "Seepage through a sand column: the pond above it, the chamber below", "time (s)",
                "water depth (m)",
                {{csv, 1, 2, "pond, Lituya", true},
                 {csv, 1, 3, "pond, Darcy-Forchheimer (Ergun) with the column's storage"},
                 {csv, 1, 4, "pond, Ergun steady (no storage)"},
                 {csv, 1, 5, "chamber, Lituya", true},
                 {csv, 1, 6, "chamber, Ergun with storage"},
                 {csv, 1, 7, "water gained by the sand", true}});
  result.plots.push_back(
      std::filesystem::relative(context.work / "pond_depth.png", context.report));
}

}  // namespace lituya::verify
