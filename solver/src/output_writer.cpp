#include "lituya/solver/output_writer.hpp"

#include <algorithm>
#include <cstdio>
#include <iomanip>
#include <sstream>

#include "lituya/common/atomic_file.hpp"

namespace lituya::solver {

namespace {
// Pads vectors to 3 components, as VTK expects.
template <int dim>
std::vector<double> as_xyz(const std::vector<Eigen::Matrix<double, dim, 1>>& v) {
  std::vector<double> out(3 * v.size(), 0.0);
  for (std::size_t i = 0; i < v.size(); ++i)
    for (int d = 0; d < dim; ++d) out[3 * i + d] = v[i](d);
  return out;
}

// The run-wide series (one per point set and the grid) play all stages on one clock; their
// names cannot be those of a stage's series, which are "<stage>_<set>".
constexpr const char* kRunSeries[] = {"points", "liquid", "grid"};

// Every file carries its times as field data: TimeValue, the run time ParaView shows when the
// .vtu files are opened as a file series without a .pvd, and the time within the stage, the
// clock of the stage's .pvd and of [post] (profile_times).
void add_times(VtuWriter& w, const FrameTimes& times) {
  const double run[] = {times.run};
  const double stage[] = {times.stage};
  w.add_field_data("TimeValue", run);
  w.add_field_data("stage_time", stage);
}

VtuWriter new_writer(const OutputSettings& settings, const FrameTimes& times) {
  VtuWriter w;
  w.set_compression(settings.compress ? VtuCompression::kZlib : VtuCompression::kNone);
  add_times(w, times);
  return w;
}
}  // namespace

namespace {
struct FieldNote {
  const char* name;
  const char* components;
  const char* unit;  // "mass" and "volume" are replaced by the units of the dimension
  const char* meaning;
};

// One entry per field of kSolidPointFields, kLiquidPointFields and kGridFields (a field
// without a note is caught by the test of output_readme).
constexpr FieldNote kSolidNotes[] = {
    {"displacement", "3", "m",
     "displacement since the start of the stage (a quasi-static stage with reset_displacement "
     "sets it to 0 at its end)"},
    {"velocity", "3", "m/s", "velocity of the soil skeleton"},
    {"stress", "6", "Pa",
     "effective stress of the soil skeleton (the pore pressure is not in it), TENSION "
     "POSITIVE; components xx, yy, zz, xy, yz, xz (ParaView: XX, YY, ZZ, XY, YZ, XZ); the "
     "mean pressure, compression positive, is -(xx + yy + zz) / 3"},
    {"plastic_strain", "1", "-",
     "accumulated equivalent plastic strain, sum of sqrt(2/3 de_p : de_p); large in shear zones"},
    {"material", "1", "-", "material id: position in materials.toml, counting from 0"},
    {"mass", "1", "mass", "mass of the solid grains of the point"},
    {"volume", "1", "volume", "volume of the point (grains and pores)"},
    {"porosity", "1", "-", "porosity n = 1 - mass / (solid_density volume), pore volume / volume"},
};
constexpr FieldNote kLiquidNotes[] = {
    {"velocity", "3", "m/s", "velocity of the water"},
    {"pressure", "1", "Pa",
     "water pressure above the atmosphere's, COMPRESSION POSITIVE, never below 0 (water "
     "takes no tension); with [solver] liquid_pressure = \"nodal_fit\" the fitted pressure the "
     "forces act with, which a linear fit can take a little below 0 at a free surface"},
    {"porosity", "1", "-",
     "porosity n the point sees: 1 in free water, that of the soil for pore water"},
    {"mass", "1", "mass", "mass of the water of the point"},
    {"volume", "1", "volume", "volume of the water of the point (mixture volume times n)"},
    {"material", "1", "-", "material id of the water: position in materials.toml, from 0"},
    {"in_flight", "1", "-",
     "1 while the point's body of water rests on nothing (no wall, no grains at its nodes): "
     "spray in free flight, merged into the water it lands on ([solver] liquid_landing); else "
     "0, and always 0 with liquid_landing = \"keep_velocity\""},
};
constexpr FieldNote kGridNotes[] = {
    {"mass", "1", "mass", "nodal mass of the soil skeleton (solid points mapped to the node)"},
    {"velocity", "3", "m/s", "nodal velocity of the soil skeleton"},
    {"liquid_mass", "1", "mass", "nodal mass of the water"},
    {"liquid_velocity", "3", "m/s", "nodal velocity of the water"},
    {"porosity", "1", "-", "nodal porosity"},
    {"liquid_pressure", "1", "Pa", "volume-weighted nodal water pressure, COMPRESSION POSITIVE"},
};

void describe_fields(std::ostream& out, std::span<const FieldNote> notes,
                     const std::vector<std::string>& selected, const char* key, int dimension,
                     const char* id_meaning) {
  auto unit = [&](const std::string& u) -> std::string {
    if (u == "mass") return dimension == 2 ? "kg/m" : "kg";
    if (u == "volume") return dimension == 2 ? "m^2" : "m^3";
    return u;
  };
  // Meanings are wrapped to 100 columns, continued under the meaning column.
  auto line = [&](const std::string& name, const std::string& components, const std::string& u,
                  const std::string& meaning) {
    constexpr std::size_t kIndent = 33, kWidth = 100;
    std::ostringstream row;
    row << "  " << std::left << std::setw(17) << name << std::setw(7) << components << std::setw(7)
        << u;
    std::string text = row.str();
    std::size_t column = text.size();
    std::istringstream words(meaning);
    std::string word;
    bool first = true;
    while (words >> word) {
      if (!first && column + 1 + word.size() > kWidth) {
        text += "\n" + std::string(kIndent, ' ');
        column = kIndent;
      } else if (!first) {
        text += ' ';
        ++column;
      }
      text += word;
      column += word.size();
      first = false;
    }
    out << text << "\n";
  };
  out << "  field            comp.  unit   meaning\n";
  if (id_meaning) line("id", "1", "-", std::string(id_meaning) + " (always written)");
  std::string dropped;
  for (const FieldNote& n : notes) {
    if (std::find(selected.begin(), selected.end(), n.name) == selected.end()) {
      dropped += (dropped.empty() ? "" : ", ") + std::string(n.name);
      continue;
    }
    line(n.name, n.components, unit(n.unit), n.meaning);
  }
  if (!dropped.empty())
    out << "  Not written (left out of [output] " << key << "): " << dropped << "\n";
}
}  // namespace

std::string output_readme(const OutputSettings& settings, int dimension, bool has_liquid) {
  std::ostringstream out;
  out << "Lituya output: what each file holds\n"
         "===================================\n\n"
         "Units are SI. Vectors have 3 components (x, y, z). "
      << (dimension == 2 ? "The case is 2D (plane strain): z\ncomponents are 0, and masses "
                           "and volumes are per metre of thickness.\n"
                         : "The case is 3D.\n")
      << "Stresses are tension positive; water pressures are compression positive.\n\n"
         "Series (open a .pvd in ParaView, press Apply, then Play):\n"
         "  points.pvd"
      << (has_liquid ? ", liquid.pvd" : "") << (settings.grid ? ", grid.pvd" : "")
      << "\n"
         "      the whole run: time runs on across stages (a stage starts at the end time of the\n"
         "      one before; at that instant the series shows the new stage's first frame).\n"
         "  <stage>_points.pvd"
      << (has_liquid ? ", <stage>_liquid.pvd" : "") << (settings.grid ? ", <stage>_grid.pvd" : "")
      << "\n"
         "      one stage: time starts at 0 at the stage's start. This is the clock of\n"
         "      `lituya post` and of [post] profile_times.\n\n"
         "Every .vtu file also holds two field-data values (ParaView: Information tab, or a\n"
         "file series opened without its .pvd):\n"
         "  TimeValue    s   time since the start of the run (the run-wide .pvd's time)\n"
         "  stage_time   s   time since the start of the file's stage\n"
      << (settings.compress
              ? "The arrays are zlib-compressed (VTK's vtkZLibDataCompressor): ParaView and VTK "
                "read them.\n"
              : "The arrays are not compressed ([output] compression = \"none\").\n")
      << "\nSolid points (soil grains and skeleton): <stage>_points_NNNN.vtu\n";
  describe_fields(out, kSolidNotes, settings.point_fields, "point_fields", dimension,
                  "index of the point in the case's points.vtu");
  if (has_liquid) {
    out << "\nLiquid points (free and pore water): <stage>_liquid_NNNN.vtu\n";
    describe_fields(out, kLiquidNotes, settings.liquid_fields, "liquid_fields", dimension,
                    "index of the point in the case's liquid_points.vtu");
  }
  if (settings.grid) {
    std::vector<std::string> grid_fields;
    for (const std::string& f : settings.grid_fields)
      if (has_liquid || f == "mass" || f == "velocity") grid_fields.push_back(f);
    out << "\nBackground grid: <stage>_grid_NNNN.vtu (the mesh's nodes and cells are in every\n"
           "file: a VTU file cannot refer to another file's geometry)\n";
    describe_fields(out,
                    has_liquid ? std::span<const FieldNote>(kGridNotes)
                               : std::span<const FieldNote>(kGridNotes, 2),
                    grid_fields, "grid_fields", dimension, nullptr);
  }
  out << "\nAlso here: log.txt (what the run printed) and summary.toml (the state of the run,\n"
         "and per stage its steps, simulated and wall time, and why it stopped);\n"
         "<stage>_history.csv (per stage: time, time step, kinetic energy of each phase in J\n"
         "(per metre in 2D), largest point speed in m/s, and wall_<boundary>_... the mean\n"
         "force in N (per metre in 2D) on each boundary the stage holds, its normal and\n"
         "tangential parts and, on a contact wall under water, the effective normal force);\n"
         "probes/<name>.csv (the scene's\n"
         "[[probe]] records, same units and signs as above); checkpoints/ (the state for\n"
         "`lituya solve --resume` and --from-stage; binary, see manuals/file-formats.md).\n";
  return out.str();
}

template <int dim>
void OutputWriter<dim>::write_readme(bool has_liquid) const {
  write_file_atomically(folder_ / "README.txt", output_readme(settings_, dim, has_liquid));
}

template <int dim>
OutputWriter<dim>::OutputWriter(std::filesystem::path folder, OutputSettings settings)
    : folder_(std::move(folder)), settings_(std::move(settings)) {
  std::filesystem::create_directories(folder_);
}

template <int dim>
std::vector<SeriesRecord> OutputWriter<dim>::series() const {
  std::vector<SeriesRecord> records;
  for (const auto& [name, writer] : series_)
    records.push_back({name, writer->file().filename().string(), writer->entries()});
  return records;
}

template <int dim>
void OutputWriter<dim>::restore_series(const std::vector<SeriesRecord>& series) {
  for (const SeriesRecord& r : series)
    series_[r.name] = std::make_unique<PvdWriter>(folder_ / r.file, r.entries);
}

template <int dim>
double OutputWriter<dim>::stage_start(const std::string& stage) {
  // Found once per stage, so that the run times of its frames are its start plus their stage
  // time exactly, with no rounding carried from one frame to the next.
  if (const auto known = stage_start_.find(stage); known != stage_start_.end())
    return known->second;
  // The points' series are always written, so they carry the clocks. A stage that has no
  // frame yet starts where the run's series ends (0 for the first stage): at the previous
  // stage's last frame, which is its end. A stage resumed from a checkpoint has frames: its
  // start is the run time the run's series gives its first frame (exact, so that a resumed
  // run writes the same bytes as one never interrupted).
  const auto run = series_.find(kRunSeries[0]);
  double start = 0.0;
  if (run != series_.end() && !run->second->entries().empty()) {
    const auto& entries = run->second->entries();
    start = entries.back().first;
    const auto own = series_.find(stage + "_points");
    if (own != series_.end() && !own->second->entries().empty()) {
      const std::string& first = own->second->entries().front().second;
      const auto at = std::find_if(entries.begin(), entries.end(),
                                   [&](const PvdWriter::Entry& e) { return e.second == first; });
      start = at != entries.end() ? at->first
                                  : entries.back().first - own->second->entries().back().first;
    }
  }
  stage_start_[stage] = start;
  return start;
}

template <int dim>
void OutputWriter<dim>::add_frame(const std::string& set, const Stage& stage,
                                  const FrameTimes& times, const std::string& file) {
  auto& stage_series = series_[stage.name + "_" + set];
  if (!stage_series)
    stage_series = std::make_unique<PvdWriter>(folder_ / (stage.name + "_" + set + ".pvd"));
  stage_series->add(times.stage, file);
  auto& run_series = series_[set];
  if (!run_series) run_series = std::make_unique<PvdWriter>(folder_ / (set + ".pvd"));
  // A stage's first frame is the previous stage's last state at the same run time: one frame
  // per time in the run's series, the one that starts the next stage (ParaView cannot show two
  // frames at one time, and a quasi-static stage resets the displacement between the two).
  run_series->add_or_replace_last(times.run, file);
}

template <int dim>
void OutputWriter<dim>::write(Simulation<dim>& simulation, const Stage& stage, double time,
                              int index) {
  if (!readme_written_) {
    write_readme(simulation.has_liquid());
    readme_written_ = true;
  }
  const FrameTimes times{stage_start(stage.name) + time, time};
  char number[16];
  std::snprintf(number, sizeof number, "%04d", index);
  const std::string points_name = stage.name + "_points_" + number + ".vtu";
  write_points(simulation, times, folder_ / points_name);
  add_frame("points", stage, times, points_name);
  if (simulation.has_liquid()) {
    const std::string liquid_name = stage.name + "_liquid_" + number + ".vtu";
    write_liquid(simulation, times, folder_ / liquid_name);
    add_frame("liquid", stage, times, liquid_name);
  }
  if (settings_.grid) {
    const std::string grid_name = stage.name + "_grid_" + number + ".vtu";
    write_grid(simulation, times, folder_ / grid_name);
    add_frame("grid", stage, times, grid_name);
  }
}

template <int dim>
void OutputWriter<dim>::write_points(const Simulation<dim>& simulation, const FrameTimes& times,
                                     const std::filesystem::path& file) const {
  const MaterialPoints<dim>& p = simulation.points();
  const std::vector<std::string>& fields = settings_.point_fields;
  auto wants = [&](const char* field) { return settings_.writes(fields, field); };
  VtuWriter w = new_writer(settings_, times);
  w.set_points(as_xyz<dim>(p.position));
  w.set_vertex_cells();
  w.add_point_data("id", p.id);
  if (wants("displacement")) w.add_point_data("displacement", 3, as_xyz<dim>(p.displacement));
  if (wants("velocity")) w.add_point_data("velocity", 3, as_xyz<dim>(p.velocity));
  if (wants("stress")) {
    std::vector<double> s(6 * p.size());
    for (std::size_t i = 0; i < p.size(); ++i)
      for (int k = 0; k < 6; ++k) s[6 * i + k] = p.stress[i](k);
    w.add_point_data("stress", 6, s);
  }
  if (wants("plastic_strain")) w.add_point_data("plastic_strain", 1, p.plastic_strain);
  if (wants("material")) w.add_point_data("material", p.material);
  if (wants("mass")) w.add_point_data("mass", 1, p.mass);
  if (wants("volume")) w.add_point_data("volume", 1, p.volume);
  if (wants("porosity")) {
    std::vector<double> n(p.size());
    for (std::size_t i = 0; i < p.size(); ++i) n[i] = simulation.porosity(i);
    w.add_point_data("porosity", 1, n);
  }
  w.write(file);
}

template <int dim>
void OutputWriter<dim>::write_liquid(const Simulation<dim>& simulation, const FrameTimes& times,
                                     const std::filesystem::path& file) const {
  const LiquidPoints<dim>& q = simulation.liquid();
  auto wants = [&](const char* field) { return settings_.writes(settings_.liquid_fields, field); };
  VtuWriter w = new_writer(settings_, times);
  w.set_points(as_xyz<dim>(q.position));
  w.set_vertex_cells();
  w.add_point_data("id", q.id);
  if (wants("velocity")) w.add_point_data("velocity", 3, as_xyz<dim>(q.velocity));
  if (wants("pressure")) w.add_point_data("pressure", 1, simulation.acting_liquid_pressure());
  if (wants("porosity")) w.add_point_data("porosity", 1, q.porosity);
  if (wants("mass")) w.add_point_data("mass", 1, q.mass);
  if (wants("volume")) w.add_point_data("volume", 1, q.volume);
  if (wants("material")) w.add_point_data("material", q.material);
  if (wants("in_flight"))
    w.add_point_data("in_flight",
                     std::vector<std::int32_t>(q.in_flight.begin(), q.in_flight.end()));
  w.write(file);
}

template <int dim>
void OutputWriter<dim>::write_grid(Simulation<dim>& simulation, const FrameTimes& times,
                                   const std::filesystem::path& file) const {
  simulation.map_to_grid();
  const Mesh<dim>& mesh = simulation.mesh();
  auto wants = [&](const char* field) { return settings_.writes(settings_.grid_fields, field); };
  VtuWriter w = new_writer(settings_, times);
  // The mesh does not move, yet every grid file holds it: a VTU file cannot refer to the
  // geometry of another file. Compressed, the repeated nodes and cells take a third of their
  // raw size (Case B: 62 kB of each 96 kB grid file, 15 % of the run's output; user manual,
  // section 5); `[output] grid = false` drops them.
  w.set_points(as_xyz<dim>(mesh.node_position));
  std::vector<std::int64_t> connectivity, offsets;
  connectivity.reserve(mesh.cell_count() * (dim + 1));
  for (const auto& cell : mesh.cell_nodes) {
    for (int n : cell) connectivity.push_back(n);
    offsets.push_back(static_cast<std::int64_t>(connectivity.size()));
  }
  w.set_cells(std::move(connectivity), std::move(offsets),
              std::vector<std::uint8_t>(mesh.cell_count(),
                                        static_cast<std::uint8_t>(dim == 2 ? VtkCellType::kTriangle
                                                                           : VtkCellType::kTetra)));
  if (wants("mass")) w.add_point_data("mass", 1, simulation.node_mass());
  if (wants("velocity")) w.add_point_data("velocity", 3, as_xyz<dim>(simulation.grid_velocity()));
  if (simulation.has_liquid()) {
    if (wants("liquid_mass")) w.add_point_data("liquid_mass", 1, simulation.node_liquid_mass());
    if (wants("liquid_velocity"))
      w.add_point_data("liquid_velocity", 3, as_xyz<dim>(simulation.grid_liquid_velocity()));
    if (wants("porosity")) w.add_point_data("porosity", 1, simulation.node_porosity());
    if (wants("liquid_pressure"))
      w.add_point_data("liquid_pressure", 1, simulation.node_pressure());
  }
  w.write(file);
}

template class OutputWriter<2>;
template class OutputWriter<3>;

}  // namespace lituya::solver
