#include "lituya/solver/probe_recorder.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>

#include "lituya/common/input_error.hpp"

namespace lituya::solver {

namespace fs = std::filesystem;

namespace {

constexpr double kNoValue = std::numeric_limits<double>::quiet_NaN();
constexpr const char* kAxes = "xyz";
constexpr const char* kStressComponents[] = {"xx", "yy", "zz", "xy", "yz", "xz"};

// The stress components a table holds: plane strain keeps zz (it is not zero) but has no
// out-of-plane shear.
int stress_components(int dim) {
  return dim == 2 ? 4 : 6;
}

// The records of a CSV table written by CsvWriter, header first; empty when there is no file.
std::vector<std::vector<std::string>> read_table(const fs::path& file) {
  std::vector<std::vector<std::string>> rows;
  std::ifstream in(file);
  std::string line;
  while (std::getline(in, line))
    if (!line.empty()) rows.push_back(csv_split(line));
  return rows;
}

// Puts back into `table` the rows of `file` that `keep` accepts, when the file has the same
// header (a table of other columns belongs to other probe settings and is started afresh).
template <class Keep>
void reload_rows(const fs::path& file, const std::vector<std::string>& header, CsvWriter& table,
                 Keep keep) {
  const auto rows = read_table(file);
  if (rows.empty() || rows.front() != header) return;
  for (std::size_t r = 1; r < rows.size(); ++r) {
    if (rows[r].size() != header.size() || !keep(rows[r])) continue;
    for (const std::string& field : rows[r]) table.text(field);
    table.end_row();
  }
}

// Stage time column of a row (column 3 of both tables); NaN when it does not parse.
double stage_time_of(const std::vector<std::string>& row) {
  try {
    return std::stod(row.at(2));
  } catch (const std::exception&) {
    return kNoValue;
  }
}

}  // namespace

double run_time_at_stage_start(const std::vector<StageReport>& finished_stages) {
  double start = 0.0;
  for (const StageReport& r : finished_stages) start = start + r.simulated_time;
  return start;
}

template <int dim>
std::vector<unsigned char> probe_patch(const Mesh<dim>& mesh, int cell) {
  std::vector<unsigned char> patch(mesh.cell_count(), 0);
  const auto& probe_nodes = mesh.cell_nodes[static_cast<std::size_t>(cell)];
  for (std::size_t c = 0; c < mesh.cell_count(); ++c)
    for (int node : mesh.cell_nodes[c])
      for (int j = 0; j <= dim; ++j)
        if (node == probe_nodes[j]) patch[c] = 1;
  return patch;
}

template <int dim>
ProbeValues interpolate_probe(const Simulation<dim>& simulation, int cell,
                              const typename Mesh<dim>::Shape& shape,
                              const std::vector<double>& node_mesh_volume,
                              const std::vector<unsigned char>* patch) {
  using Vec = Eigen::Matrix<double, dim, 1>;
  const Mesh<dim>& mesh = simulation.mesh();
  const auto& probe_nodes = mesh.cell_nodes[cell];
  struct NodeSums {
    double mass = 0, volume = 0, grain_volume = 0;
    Vec momentum = Vec::Zero();
    Voigt6 stress_volume = Voigt6::Zero();
    double liquid_mass = 0, liquid_volume = 0, pressure_volume = 0;
    Vec liquid_momentum = Vec::Zero();
  };
  std::array<NodeSums, dim + 1> sums{};
  // Adds every point of a cell that shares a node with the probe's cell, with the weight of
  // its shape function at that node.
  auto scatter = [&](const auto& points, auto&& add) {
    for (std::size_t p = 0; p < points.size(); ++p) {
      const int c = points.cell[p];
      if (c < 0) continue;
      if (patch && !(*patch)[static_cast<std::size_t>(c)]) continue;
      const auto& nodes = mesh.cell_nodes[c];
      bool near = patch != nullptr;
      for (int k = 0; k <= dim && !near; ++k)
        for (int j = 0; j <= dim; ++j) near = near || nodes[k] == probe_nodes[j];
      if (!near) continue;
      const typename Mesh<dim>::Shape n = mesh.shape_values(c, points.position[p]);
      for (int k = 0; k <= dim; ++k)
        for (int j = 0; j <= dim; ++j)
          if (nodes[k] == probe_nodes[j]) add(sums[j], p, n(k));
    }
  };
  const MaterialPoints<dim>& solid = simulation.points();
  scatter(solid, [&](NodeSums& s, std::size_t p, double w) {
    s.mass += w * solid.mass[p];
    s.momentum += w * solid.mass[p] * solid.velocity[p];
    s.volume += w * solid.volume[p];
    s.stress_volume += w * solid.volume[p] * solid.stress[p];
    s.grain_volume += w * solid.volume[p] * (1.0 - simulation.porosity(p));
  });
  const LiquidPoints<dim>& liquid = simulation.liquid();
  scatter(liquid, [&](NodeSums& s, std::size_t q, double w) {
    s.liquid_mass += w * liquid.mass[q];
    s.liquid_momentum += w * liquid.mass[q] * liquid.velocity[q];
    s.liquid_volume += w * liquid.volume[q];
    s.pressure_volume += w * liquid.volume[q] * liquid.pressure[q];
  });

  // sum_j N_j f_j over the nodes that have the phase (weight > 0), renormalised by their share
  // of the partition of unity: next to a free surface or the edge of a slide the nodes outside
  // the phase do not drag the value towards zero.
  auto blend = [&](auto weight_of, auto value_of, auto zero) {
    auto total = zero;
    double share = 0;
    for (int j = 0; j <= dim; ++j) {
      const double weight = weight_of(sums[j]);
      if (!(weight > 0) || shape(j) <= 0) continue;
      total += shape(j) * value_of(sums[j], weight);
      share += shape(j);
    }
    return std::make_pair(total, share);
  };
  ProbeValues v;
  {
    auto [p, share] = blend([](const NodeSums& s) { return s.liquid_volume; },
                            [](const NodeSums& s, double w) { return s.pressure_volume / w; }, 0.0);
    // With liquid_pressure = "nodal_fit" the nodes' fitted pressures, the ones the forces act
    // with (the points' own values carry a part no force feels).
    if (const std::vector<double>* fitted = simulation.fitted_node_pressure()) {
      p = 0;
      for (int j = 0; j <= dim; ++j)
        if (sums[j].liquid_volume > 0 && shape(j) > 0)
          p += shape(j) * (*fitted)[static_cast<std::size_t>(probe_nodes[j])];
    }
    v.pore_pressure = share > 0 ? p / share : kNoValue;
  }
  {
    auto [sigma, share] =
        blend([](const NodeSums& s) { return s.volume; },
              [](const NodeSums& s, double w) -> Voigt6 { return s.stress_volume / w; },
              Voigt6(Voigt6::Zero()));
    v.effective_stress = share > 0 ? Voigt6(sigma / share) : Voigt6::Constant(kNoValue);
  }
  auto velocity = [&](auto mass_of, auto momentum_of) {
    auto [u, share] = blend(
        mass_of, [&](const NodeSums& s, double m) -> Vec { return momentum_of(s) / m; },
        Vec(Vec::Zero()));
    Eigen::Vector3d out = Eigen::Vector3d::Zero();
    if (share > 0)
      out.head<dim>() = u / share;
    else
      out.setConstant(kNoValue);
    return out;
  };
  v.velocity = velocity([](const NodeSums& s) { return s.mass; },
                        [](const NodeSums& s) -> Vec { return s.momentum; });
  v.liquid_velocity = velocity([](const NodeSums& s) { return s.liquid_mass; },
                               [](const NodeSums& s) -> Vec { return s.liquid_momentum; });
  v.porosity = 0;
  for (int j = 0; j <= dim; ++j) {
    const double mesh_volume = node_mesh_volume[probe_nodes[j]];
    const double n = mesh_volume > 0 ? 1.0 - sums[j].grain_volume / mesh_volume : 1.0;
    v.porosity += shape(j) * std::clamp(n, 0.0, 1.0);
  }
  return v;
}

template <int dim>
std::vector<std::string> ProbeRecorder<dim>::probe_header(const Probe& probe) {
  std::vector<std::string> h = {"time", "stage", "stage_time"};
  for (int d = 0; d < dim; ++d) h.push_back(std::string(1, kAxes[d]));
  for (const std::string& field : kProbeFields) {
    if (!probe.records(field)) continue;
    if (field == "pore_pressure" || field == "porosity") {
      h.push_back(field);
    } else if (field == "effective_stress") {
      for (int k = 0; k < stress_components(dim); ++k)
        h.push_back(field + "_" + kStressComponents[k]);
    } else {
      for (int d = 0; d < dim; ++d) h.push_back(field + "_" + kAxes[d]);
    }
  }
  return h;
}

template <int dim>
std::vector<std::string> ProbeRecorder<dim>::history_header() {
  return {"time",
          "stage",
          "stage_time",
          "step",
          "time_step",
          "kinetic_energy_solid",
          "kinetic_energy_liquid",
          "kinetic_energy",
          "max_speed_solid",
          "max_speed_liquid"};
}

// Per wall of the stage: the mean force on it over the row's interval, its components, its
// normal and tangential parts (wall_loads.cpp) and, at a contact wall with water, the
// effective normal force Coulomb's law acts on.
template <int dim>
std::vector<std::string> ProbeRecorder<dim>::wall_columns() const {
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  std::vector<std::string> columns;
  for (const Wall& wall : walls_) {
    const std::string prefix = "wall_" + wall.name + "_";
    for (int d = 0; d < dim; ++d) columns.push_back(prefix + "force_" + kAxes[d]);
    columns.push_back(prefix + "normal");
    columns.push_back(prefix + "tangential");
    if (wall.effective_normal) columns.push_back(prefix + "effective_normal");
  }
  return columns;
}

template <int dim>
ProbeRecorder<dim>::ProbeRecorder(const Simulation<dim>& simulation,
                                  const std::vector<Probe>& probes, fs::path output_folder)
    : folder_(std::move(output_folder)),
      boundaries_(simulation.description().boundaries),
      has_liquid_(simulation.has_liquid()) {
  const CaseDescription& description = simulation.description();
  const std::string stages_file = (fs::path(description.folder) / "stages.toml").string();
  const Mesh<dim>& mesh = simulation.mesh();
  if (!probes.empty()) node_mesh_volume_ = mesh.lumped_node_volume();
  for (const Probe& probe : probes) {
    Site site{probe,
              folder_ / "probes" / (probe.name + ".csv"),
              -1,
              {},
              CsvWriter(probe_header(probe)),
              {},
              1,
              -1};
    if (probe.follows == Probe::Follows::kPosition) {
      Eigen::Matrix<double, dim, 1> x;
      for (int d = 0; d < dim; ++d) x(d) = probe.position[static_cast<std::size_t>(d)];
      site.cell = mesh.locate_anywhere(x, site.shape);
      if (site.cell < 0)
        throw InputError(stages_file, 0, "probe '" + probe.name + "' lies outside the mesh");
      site.patch = probe_patch(mesh, site.cell);
    } else {
      const bool solid = probe.follows == Probe::Follows::kSolidPoint;
      const std::size_t count = solid ? simulation.points().size() : simulation.liquid().size();
      if (static_cast<std::size_t>(probe.point_id) >= count)
        throw InputError(stages_file, 0,
                         "probe '" + probe.name + "' rides on " + (solid ? "solid" : "liquid") +
                             " point " + std::to_string(probe.point_id) +
                             ", which does not exist (" + std::to_string(count) + " points)");
    }
    sites_.push_back(std::move(site));
  }
}

template <int dim>
fs::path ProbeRecorder<dim>::history_file(const std::string& stage) const {
  return folder_ / (stage + "_history.csv");
}

template <int dim>
void ProbeRecorder<dim>::restart(const std::vector<Stage>& stages, std::size_t stage,
                                 std::optional<double> within) {
  auto index_of = [&](const std::string& name) {
    for (std::size_t k = 0; k < stages.size(); ++k)
      if (stages[k].name == name) return k;
    return stages.size();  // a stage this case no longer has: dropped
  };
  for (Site& site : sites_) {
    const auto header = probe_header(site.probe);
    reload_rows(site.file, header, site.table, [&](const std::vector<std::string>& row) {
      const std::size_t k = index_of(row[1]);
      return k < stage || (k == stage && within && stage_time_of(row) <= *within);
    });
  }
  for (std::size_t k = within ? stage + 1 : stage; k < stages.size(); ++k)
    fs::remove(history_file(stages[k].name));
}

template <int dim>
void ProbeRecorder<dim>::begin_stage(const Stage& stage, double run_start,
                                     std::optional<double> resume_time) {
  stage_ = stage;
  run_start_ = run_start;
  walls_.clear();
  for (const std::string& name : stage.boundaries) {
    if (std::any_of(walls_.begin(), walls_.end(), [&](const Wall& w) { return w.name == name; }))
      continue;
    Wall wall{name, {}, false};
    for (std::size_t b = 0; b < boundaries_.size(); ++b)
      if (boundaries_[b].name == name && boundaries_[b].type != BoundaryType::kTraction) {
        wall.conditions.push_back(b);
        wall.effective_normal |= has_liquid_ && boundaries_[b].type == BoundaryType::kContact;
      }
    if (!wall.conditions.empty()) walls_.push_back(std::move(wall));
  }
  std::vector<std::string> columns = history_header();
  for (std::string& column : wall_columns()) columns.push_back(std::move(column));
  history_.emplace(columns);
  history_stage_ = stage.name;
  const double tolerance = 1e-9 * stage.duration;
  const double spacing = stage.duration / kHistoryRowsPerStage;
  // The marks already passed at `time`: the next one lies beyond it (as after_step sets it).
  auto next_after = [&](double time, double step) {
    return static_cast<long>(std::floor((time + tolerance) / step)) + 1;
  };
  next_history_mark_ = 1;
  last_history_time_ = -1;
  for (Site& site : sites_) {
    site.next_mark = 1;
    site.last_sample = -1;
  }
  if (!resume_time) return;
  reload_rows(history_file(stage.name), columns, *history_,
              [&](const std::vector<std::string>& row) {
                return row[1] == stage.name && stage_time_of(row) <= *resume_time;
              });
  next_history_mark_ = next_after(*resume_time, spacing);
  last_history_time_ = *resume_time;
  for (Site& site : sites_) {
    if (site.probe.interval > 0) site.next_mark = next_after(*resume_time, site.probe.interval);
    site.last_sample = *resume_time;
  }
}

template <int dim>
void ProbeRecorder<dim>::sample(const Simulation<dim>& simulation, Site& site, double t) {
  if (t == site.last_sample) return;  // an output at the time of a step's sample
  site.last_sample = t;
  if (site.probe.interval > 0) {
    const double tolerance = 1e-9 * stage_.duration;
    site.next_mark = static_cast<long>(std::floor((t + tolerance) / site.probe.interval)) + 1;
  }
  ProbeValues v;
  Eigen::Matrix<double, dim, 1> x;
  const Mesh<dim>& mesh = simulation.mesh();
  if (site.probe.follows == Probe::Follows::kPosition) {
    for (int d = 0; d < dim; ++d) x(d) = site.probe.position[static_cast<std::size_t>(d)];
    v = interpolate_probe(simulation, site.cell, site.shape, node_mesh_volume_, &site.patch);
  } else {
    // Points keep their id but not necessarily their place in the arrays: found by id, looked
    // for again only when the place it was last found at holds another point.
    auto find = [&](const auto& points) {
      const auto& ids = points.id;
      const int id = static_cast<int>(site.probe.point_id);
      if (site.point_index >= ids.size() || ids[site.point_index] != id)
        site.point_index =
            static_cast<std::size_t>(std::find(ids.begin(), ids.end(), id) - ids.begin());
      return site.point_index;
    };
    if (site.probe.follows == Probe::Follows::kSolidPoint) {
      const MaterialPoints<dim>& points = simulation.points();
      const std::size_t p = find(points);
      x = points.position[p];
      const int cell = points.cell[p];
      v = interpolate_probe(simulation, cell, mesh.shape_values(cell, x), node_mesh_volume_);
      v.velocity.setZero();
      v.velocity.head<dim>() = points.velocity[p];
      v.effective_stress = points.stress[p];
      v.porosity = simulation.porosity(p);
    } else {
      const LiquidPoints<dim>& points = simulation.liquid();
      const std::size_t q = find(points);
      x = points.position[q];
      const int cell = points.cell[q];
      v = interpolate_probe(simulation, cell, mesh.shape_values(cell, x), node_mesh_volume_);
      v.liquid_velocity.setZero();
      v.liquid_velocity.head<dim>() = points.velocity[q];
      v.pore_pressure = points.pressure[q];
      if (const std::vector<double>* fitted = simulation.fitted_node_pressure()) {
        const auto& nodes = mesh.cell_nodes[cell];
        const auto shape = mesh.shape_values(cell, x);
        v.pore_pressure = 0;
        for (int j = 0; j <= dim; ++j)
          v.pore_pressure += shape(j) * (*fitted)[static_cast<std::size_t>(nodes[j])];
      }
      v.porosity = points.porosity[q];
    }
  }
  CsvWriter& table = site.table;
  table.number(run_start_ + t).text(stage_.name).number(t);
  for (int d = 0; d < dim; ++d) table.number(x(d));
  for (const std::string& field : kProbeFields) {
    if (!site.probe.records(field)) continue;
    if (field == "pore_pressure") {
      table.number(v.pore_pressure);
    } else if (field == "porosity") {
      table.number(v.porosity);
    } else if (field == "effective_stress") {
      for (int k = 0; k < stress_components(dim); ++k) table.number(v.effective_stress(k));
    } else {
      const Eigen::Vector3d& u = field == "velocity" ? v.velocity : v.liquid_velocity;
      for (int d = 0; d < dim; ++d) table.number(u(d));
    }
  }
  table.end_row();
}

template <int dim>
void ProbeRecorder<dim>::history_row(Simulation<dim>& simulation, double t) {
  if (t == last_history_time_) return;
  last_history_time_ = t;
  const double tolerance = 1e-9 * stage_.duration;
  next_history_mark_ =
      static_cast<long>(std::floor((t + tolerance) / (stage_.duration / kHistoryRowsPerStage))) + 1;
  // Each phase summed in point order; the total is the simulation's own kinetic_energy(), the
  // figure the quasi-static stop criterion reads.
  auto energy_and_speed = [](const auto& points) {
    double energy = 0, speed = 0;
    for (std::size_t p = 0; p < points.size(); ++p) {
      const double v2 = points.velocity[p].squaredNorm();
      energy += 0.5 * points.mass[p] * v2;
      speed = std::max(speed, v2);
    }
    return std::make_pair(energy, std::sqrt(speed));
  };
  const auto [solid_energy, solid_speed] = energy_and_speed(simulation.points());
  const auto [liquid_energy, liquid_speed] = energy_and_speed(simulation.liquid());
  history_->number(run_start_ + t)
      .text(stage_.name)
      .number(t)
      .integer(simulation.step_count())
      .number(simulation.last_time_step())
      .number(solid_energy)
      .number(liquid_energy)
      .number(simulation.kinetic_energy())
      .number(solid_speed);
  if (simulation.has_liquid())
    history_->number(liquid_speed);
  else
    history_->number(kNoValue);
  // The walls: mean forces since the last row (N, per metre in 2D). The simulation sums
  // them from the row before (a checkpoint holds the sums, so a resumed run writes the rows
  // of a run never stopped).
  const double span = simulation.take_wall_impulses(wall_impulses_);
  for (const Wall& wall : walls_) {
    typename Simulation<dim>::WallImpulse sum;
    for (std::size_t b : wall.conditions) {
      if (b >= wall_impulses_.size()) continue;
      sum.force += wall_impulses_[b].force;
      sum.normal += wall_impulses_[b].normal;
      sum.tangential += wall_impulses_[b].tangential;
      sum.pore_pressure += wall_impulses_[b].pore_pressure;
    }
    const int values = dim + 2 + (wall.effective_normal ? 1 : 0);
    if (!(span > 0)) {
      for (int k = 0; k < values; ++k) history_->number(kNoValue);
      continue;
    }
    for (int d = 0; d < dim; ++d) history_->number(sum.force(d) / span);
    history_->number(sum.normal / span).number(sum.tangential.norm() / span);
    if (wall.effective_normal) history_->number((sum.normal - sum.pore_pressure) / span);
  }
  history_->end_row();
}

template <int dim>
void ProbeRecorder<dim>::at_output(Simulation<dim>& simulation, double t) {
  for (Site& site : sites_) sample(simulation, site, t);
  if (t > 0) history_row(simulation, t);  // the stage's start has no step yet
  write();
}

template <int dim>
void ProbeRecorder<dim>::after_step(Simulation<dim>& simulation, double t) {
  const double tolerance = 1e-9 * stage_.duration;
  for (Site& site : sites_)
    if (site.probe.interval > 0 &&
        t >= static_cast<double>(site.next_mark) * site.probe.interval - tolerance)
      sample(simulation, site, t);
  if (t >=
      static_cast<double>(next_history_mark_) * stage_.duration / kHistoryRowsPerStage - tolerance)
    history_row(simulation, t);
}

template <int dim>
void ProbeRecorder<dim>::write() const {
  if (!sites_.empty()) fs::create_directories(folder_ / "probes");
  for (const Site& site : sites_) site.table.write(site.file);
  if (history_) history_->write(history_file(history_stage_));
}

template class ProbeRecorder<2>;
template class ProbeRecorder<3>;
template ProbeValues interpolate_probe<2>(const Simulation<2>&, int, const Mesh<2>::Shape&,
                                          const std::vector<double>&,
                                          const std::vector<unsigned char>*);
template ProbeValues interpolate_probe<3>(const Simulation<3>&, int, const Mesh<3>::Shape&,
                                          const std::vector<double>&,
                                          const std::vector<unsigned char>*);
template std::vector<unsigned char> probe_patch<2>(const Mesh<2>&, int);
template std::vector<unsigned char> probe_patch<3>(const Mesh<3>&, int);

}  // namespace lituya::solver
