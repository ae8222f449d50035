// Throughput benchmark: a dry Mohr-Coulomb column collapse (>= 100k points) on a structured
// triangle (2D) or tetrahedron (3D) mesh. Reports point-steps per second (median of several
// timed segments, one core unless --threads is given) and bytes per point. With --water 1 the
// column is saturated and collapses into a pool of still water 0.3 m deep (two-phase: solid
// and liquid points both count as points).
//
//   lituya_benchmark [--dim 2|3] [--segments 5] [--steps 50] [--threads 1] [--cell 0.005]
//                    [--water 0|1] [--nodal-fit 0|1] [--landing 1|0] [--crossed-filter 1|0]
// --nodal-fit 1 runs the water with [solver] liquid_pressure = "nodal_fit"; --landing 0 with
// liquid_landing = "keep_velocity" (no search for water in free flight; the cost of that search);
// --crossed-filter 0 with crossed_pressure_filter = false (the box mesh's alternating diagonals
// make it a crossed mesh: every other node is the centre of four cells; the cost of the filter).
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "lituya/common/process_memory.hpp"
#include "lituya/solver/box_scene.hpp"

using namespace lituya::solver;

namespace {

Material sand() {
  Material m;
  m.name = "sand";
  m.model = MaterialModel::kMohrCoulomb;
  m.solid_density = 2500;
  m.porosity = 0.4;
  m.youngs_modulus = 2e7;
  m.poisson_ratio = 0.3;
  m.friction_angle = 30;
  m.grain_diameter = 0.002;
  return m;
}

template <int dim>
void run(int segments, int steps, int threads, double cell, bool with_water, bool nodal_fit,
         bool landing, bool crossed_filter) {
  const std::size_t memory_before = lituya::current_memory_bytes();
  BoxScene<dim> scene;
  using Vec = Eigen::Matrix<double, dim, 1>;
  if constexpr (dim == 2) {
    scene.domain_size = Vec(3.0, 0.6);
    scene.block_max = Vec(1.0, 0.5);
  } else {
    scene.domain_size = Vec(1.5, 0.6, 0.2);
    scene.block_max = Vec(0.5, 0.4, 0.2);
  }
  for (int d = 0; d < dim; ++d)
    scene.cells[d] = static_cast<int>(std::lround(scene.domain_size(d) / cell));
  scene.material = sand();
  if (with_water) {
    // Water up to y = 0.3 m everywhere: the lower part of the column is saturated, the rest
    // of the floor is a pool of free water.
    scene.with_water = true;
    scene.water = paper_water();
    if (nodal_fit) scene.solver.liquid_pressure = LiquidPressure::kNodalFit;
    if (!landing) scene.solver.liquid_landing = LiquidLanding::kKeepVelocity;
    scene.solver.crossed_pressure_filter = crossed_filter;
    scene.water_min = Vec::Zero();
    scene.water_max = scene.domain_size;
    scene.water_max(1) = 0.3;
  }
  scene.gravity.assign(dim, 0.0);
  scene.gravity[1] = -9.81;
  scene.boundaries = {{"x-", box_condition(BoundaryType::kRoller)},
                      {"y-", box_condition(BoundaryType::kContact, 0.4)},
                      {"x+", box_condition(BoundaryType::kRoller)}};
  if (dim == 3)
    scene.boundaries.push_back({"z-", box_condition(BoundaryType::kRoller)}),
        scene.boundaries.push_back({"z+", box_condition(BoundaryType::kRoller)});
  Simulation<dim> sim = make_box_simulation<dim>(scene);
  sim.set_threads(threads);
  std::vector<std::string> names;
  for (const auto& b : sim.description().boundaries) names.push_back(b.name);
  sim.activate_boundaries(names);
  const std::size_t n = sim.point_count();
  // Warm up: the collapse starts and caches fill.
  for (int i = 0; i < 10; ++i) sim.step(0.5 * sim.stable_time_step(1.0), 0.0);
  std::vector<double> rates;
  for (int s = 0; s < segments; ++s) {
    const auto start = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) sim.step(0.5 * sim.stable_time_step(1.0), 0.0);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rates.push_back(static_cast<double>(n) * steps / seconds);
  }
  std::sort(rates.begin(), rates.end());
  const double median = rates[rates.size() / 2];
  const std::size_t peak = lituya::peak_memory_bytes();
  std::printf(
      "dim=%d points=%zu (liquid %zu) cells=%zu nodes=%zu threads=%d steps=%d x %d\n"
      "  point-steps/s: median %.3e (min %.3e, max %.3e)\n"
      "  memory: solver storage %.0f B/point; process peak %.1f MiB, growth %.0f B/point\n",
      dim, n, sim.liquid().size(), sim.mesh().cell_count(), sim.mesh().node_count(), threads,
      segments, steps, median, rates.front(), rates.back(),
      static_cast<double>(sim.storage_bytes()) / n, peak / 1048576.0,
      static_cast<double>(peak - memory_before) / n);
}

}  // namespace

int main(int argc, char** argv) {
  const char* usage =
      "usage: lituya_benchmark [--dim 2|3] [--segments 5] [--steps 50] [--threads 1]\n"
      "                        [--cell 0.005] [--water 0|1] [--nodal-fit 0|1] [--landing 1|0]\n"
      "                        [--crossed-filter 1|0]\n";
  int dim = 2, segments = 5, steps = 50, threads = 1, water = 0, nodal_fit = 0, landing = 1,
      crossed_filter = 1;
  double cell = -1;
  for (int i = 1; i < argc; i += 2) {
    if (!std::strcmp(argv[i], "--help") || !std::strcmp(argv[i], "-h")) {
      std::fputs(usage, stdout);
      return 0;
    }
    // Every option takes a value: a lone or unknown flag is a usage error, not a run.
    bool known = false;
    for (const char* name : {"--dim", "--segments", "--steps", "--threads", "--water", "--cell",
                             "--nodal-fit", "--landing", "--crossed-filter"})
      known = known || !std::strcmp(argv[i], name);
    if (!known) {
      std::fprintf(stderr, "unknown option %s\n%s", argv[i], usage);
      return 1;
    }
    if (i + 1 >= argc) {
      std::fprintf(stderr, "option %s needs a value\n%s", argv[i], usage);
      return 1;
    }
    if (!std::strcmp(argv[i], "--dim"))
      dim = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--segments"))
      segments = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--steps"))
      steps = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--threads"))
      threads = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--water"))
      water = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--nodal-fit"))
      nodal_fit = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--landing"))
      landing = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--crossed-filter"))
      crossed_filter = std::atoi(argv[i + 1]);
    else
      cell = std::atof(argv[i + 1]);
  }
  if (dim == 2)
    run<2>(segments, steps, threads, cell > 0 ? cell : 0.005, water != 0, nodal_fit != 0,
           landing != 0, crossed_filter != 0);
  else
    run<3>(segments, steps, threads, cell > 0 ? cell : 0.02, water != 0, nodal_fit != 0,
           landing != 0, crossed_filter != 0);
  return 0;
}
