#include "lituya/solver/checkpoint.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <tuple>
#include <type_traits>

#include <toml++/toml.h>
#include <Eigen/Core>

#include "lituya/common/atomic_file.hpp"
#include "lituya/common/content_hash.hpp"
#include "lituya/common/input_error.hpp"
#include "lituya/common/provenance.hpp"
#include "lituya/solver/solve.hpp"

namespace lituya::solver {

namespace fs = std::filesystem;

namespace {

// "LITUYACK": the first 8 bytes of every checkpoint.
constexpr std::array<char, 8> kMagic = {'L', 'I', 'T', 'U', 'Y', 'A', 'C', 'K'};
// Written in the machine's byte order: a reader on a machine of the other order sees
// 0x04030201 and refuses the file instead of reading every number wrong.
constexpr std::uint32_t kByteOrderMark = 0x01020304;
// A string longer than this in a checkpoint means a damaged file (names, dates and hashes
// are short): refuse it before allocating.
constexpr std::uint64_t kLongestText = 1 << 20;

// Types whose memory is their value and nothing else, written as raw bytes: numbers, and
// fixed-size Eigen vectors of doubles (a plain array of doubles, not trivially copyable only
// because Eigen declares its own copy constructor).
template <class T>
constexpr bool kPlainBytes = std::is_trivially_copyable_v<T>;
template <int rows, int cols, int options, int max_rows, int max_cols>
constexpr bool kPlainBytes<Eigen::Matrix<double, rows, cols, options, max_rows, max_cols>> =
    rows > 0 && cols > 0 &&
    sizeof(Eigen::Matrix<double, rows, cols, options, max_rows, max_cols>) ==
        static_cast<std::size_t>(rows* cols) * sizeof(double);

std::string hex_hash(std::uint64_t value) {
  char text[32];
  std::snprintf(text, sizeof text, "fnv1a64:%016llx", static_cast<unsigned long long>(value));
  return text;
}

// Bytes out, with the running checksum of everything written.
class BinaryOut {
 public:
  explicit BinaryOut(std::ostream& out) : out_(out) {}
  void bytes(const void* data, std::size_t n) {
    const std::string_view view(static_cast<const char*>(data), n);
    out_.write(view.data(), static_cast<std::streamsize>(n));
    checksum_.add(view);
  }
  template <class T>
  void value(T v) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes(&v, sizeof v);
  }
  void text(const std::string& s) {
    value<std::uint64_t>(s.size());
    bytes(s.data(), s.size());
  }
  // A named array: name, element count, element size, then the elements' bytes as they are in
  // memory (IEEE doubles and 32-bit integers: the exact bits).
  template <class T>
  void array(const std::string& name, const std::vector<T>& v) {
    static_assert(kPlainBytes<T>);
    text(name);
    value<std::uint64_t>(v.size());
    value<std::uint32_t>(sizeof(T));
    bytes(v.data(), v.size() * sizeof(T));
  }
  std::uint64_t checksum() const { return checksum_.value(); }

 private:
  std::ostream& out_;
  Fnv1a64 checksum_;
};

// Bytes in, with the same checksum, and the error of a file that ends too soon.
class BinaryIn {
 public:
  BinaryIn(std::istream& in, fs::path file) : in_(in), file_(std::move(file)) {}
  void bytes(void* data, std::size_t n) {
    in_.read(static_cast<char*>(data), static_cast<std::streamsize>(n));
    const std::size_t got = static_cast<std::size_t>(in_.gcount());
    offset_ += got;
    if (got != n)
      fail("the file ends at byte " + std::to_string(offset_) +
           ", inside the checkpoint: it was cut short (not written whole, or truncated since)");
    checksum_.add(std::string_view(static_cast<const char*>(data), n));
  }
  template <class T>
  T value() {
    T v;
    bytes(&v, sizeof v);
    return v;
  }
  std::string text() {
    const auto n = value<std::uint64_t>();
    if (n > kLongestText) damaged("a text field of " + std::to_string(n) + " bytes");
    std::string s(n, '\0');
    bytes(s.data(), n);
    return s;
  }
  // Reads the array `name` into `v`. With `expected` its element count must be that.
  template <class T>
  void array(const std::string& name, std::vector<T>& v, std::optional<std::uint64_t> expected) {
    static_assert(kPlainBytes<T>);
    const std::string found = text();
    if (found != name) damaged("array '" + found + "' where '" + name + "' belongs");
    const auto count = value<std::uint64_t>();
    const auto size = value<std::uint32_t>();
    if (size != sizeof(T))
      damaged("array '" + name + "' has elements of " + std::to_string(size) + " bytes, not " +
              std::to_string(sizeof(T)));
    if (expected && count != *expected)
      damaged("array '" + name + "' has " + std::to_string(count) + " elements, not " +
              std::to_string(*expected));
    if (count > remaining() / sizeof(T))
      fail("array '" + name + "' needs " + std::to_string(count * sizeof(T)) + " bytes, the " +
           "file has " + std::to_string(remaining()) +
           " left: it was cut short (not written whole, or truncated since)");
    v.resize(count);
    bytes(v.data(), count * sizeof(T));
  }
  std::uint64_t checksum() const { return checksum_.value(); }
  [[noreturn]] void fail(const std::string& why) const { throw InputError(file_.string(), 0, why); }
  [[noreturn]] void damaged(const std::string& what) const {
    fail("damaged checkpoint: " + what + " (at byte " + std::to_string(offset_) + ")");
  }

 private:
  std::uint64_t remaining() {
    if (!size_) {
      std::error_code error;
      size_ = fs::file_size(file_, error);
      if (error) size_ = 0;
    }
    return *size_ > offset_ ? *size_ - offset_ : 0;
  }
  std::istream& in_;
  fs::path file_;
  std::uint64_t offset_ = 0;
  std::optional<std::uint64_t> size_;
  Fnv1a64 checksum_;
};

void write_progress(BinaryOut& out, const StageProgress& p) {
  out.value(p.time);
  out.value<std::int32_t>(p.next_output_index);
  out.value(p.next_output_time);
  out.value(p.max_kinetic_energy);
  out.value<std::int64_t>(p.steps);
  out.value(p.wall_time);
}

StageProgress read_progress(BinaryIn& in) {
  StageProgress p;
  p.time = in.value<double>();
  p.next_output_index = in.value<std::int32_t>();
  p.next_output_time = in.value<double>();
  p.max_kinetic_energy = in.value<double>();
  p.steps = in.value<std::int64_t>();
  p.wall_time = in.value<double>();
  return p;
}

void write_header(BinaryOut& out, const CheckpointHeader& h) {
  out.bytes(kMagic.data(), kMagic.size());
  out.value(kByteOrderMark);
  out.value(h.format_version);
  for (const std::string* s : {&h.lituya_version, &h.commit, &h.case_hash, &h.inputs_hash,
                               &h.started, &h.written, &h.reason})
    out.text(*s);
  out.value<std::int32_t>(h.dimension);
  out.value<std::int32_t>(h.threads);
  out.value(h.solid_points);
  out.value(h.liquid_points);
  out.value(h.nodes);
  out.value(h.step_count);
  out.value<std::int32_t>(h.stage);
  out.value<std::uint8_t>(h.within_stage ? 1 : 0);
  if (h.within_stage) write_progress(out, *h.within_stage);
}

CheckpointHeader read_header(BinaryIn& in) {
  std::array<char, 8> magic{};
  in.bytes(magic.data(), magic.size());
  if (magic != kMagic) in.fail("not a Lituya checkpoint (its first bytes are not \"LITUYACK\")");
  if (in.value<std::uint32_t>() != kByteOrderMark)
    in.fail("a checkpoint written on a machine of the other byte order; it cannot be read here");
  CheckpointHeader h;
  h.format_version = in.value<std::uint32_t>();
  if (h.format_version != kCheckpointFormatVersion)
    in.fail("checkpoint format version " + std::to_string(h.format_version) + "; this Lituya (" +
            lituya_version() + ") reads version " + std::to_string(kCheckpointFormatVersion));
  for (std::string* s : {&h.lituya_version, &h.commit, &h.case_hash, &h.inputs_hash, &h.started,
                         &h.written, &h.reason})
    *s = in.text();
  h.dimension = in.value<std::int32_t>();
  h.threads = in.value<std::int32_t>();
  h.solid_points = in.value<std::uint64_t>();
  h.liquid_points = in.value<std::uint64_t>();
  h.nodes = in.value<std::uint64_t>();
  h.step_count = in.value<std::int64_t>();
  h.stage = in.value<std::int32_t>();
  if (in.value<std::uint8_t>() != 0) h.within_stage = read_progress(in);
  if ((h.dimension != 2 && h.dimension != 3) || h.stage < 0 || h.threads < 1)
    in.damaged("dimension " + std::to_string(h.dimension) + ", stage " + std::to_string(h.stage) +
               ", threads " + std::to_string(h.threads));
  return h;
}

void write_record(BinaryOut& out, const RunRecord& r) {
  out.value<std::uint64_t>(r.reports.size());
  for (const StageReport& s : r.reports) {
    out.text(s.stage);
    out.value<std::int64_t>(s.steps);
    out.value(s.simulated_time);
    out.value(s.wall_time);
    out.value(s.point_steps_per_second);
    out.value<std::uint64_t>(s.peak_memory);
    out.text(s.stop_reason);
  }
  out.value<std::uint64_t>(r.series.size());
  for (const SeriesRecord& s : r.series) {
    out.text(s.name);
    out.text(s.file);
    out.value<std::uint64_t>(s.entries.size());
    for (const auto& [time, dataset] : s.entries) {
      out.value(time);
      out.text(dataset);
    }
  }
}

RunRecord read_record(BinaryIn& in) {
  RunRecord r;
  const auto n_reports = in.value<std::uint64_t>();
  if (n_reports > 100000) in.damaged(std::to_string(n_reports) + " stage reports");
  for (std::uint64_t i = 0; i < n_reports; ++i) {
    StageReport s;
    s.stage = in.text();
    s.steps = static_cast<long>(in.value<std::int64_t>());
    s.simulated_time = in.value<double>();
    s.wall_time = in.value<double>();
    s.point_steps_per_second = in.value<double>();
    s.peak_memory = static_cast<std::size_t>(in.value<std::uint64_t>());
    s.stop_reason = in.text();
    r.reports.push_back(std::move(s));
  }
  const auto n_series = in.value<std::uint64_t>();
  if (n_series > 100000) in.damaged(std::to_string(n_series) + " output series");
  for (std::uint64_t i = 0; i < n_series; ++i) {
    SeriesRecord s;
    s.name = in.text();
    s.file = in.text();
    const auto n_entries = in.value<std::uint64_t>();
    if (n_entries > (1ull << 32)) in.damaged(std::to_string(n_entries) + " series entries");
    for (std::uint64_t k = 0; k < n_entries; ++k) {
      const double time = in.value<double>();
      s.entries.emplace_back(time, in.text());
    }
    r.series.push_back(std::move(s));
  }
  return r;
}

}  // namespace

namespace detail {

// The simulation's state that a checkpoint holds, array by array, in file order. Reading and
// writing go through the same list, so they cannot disagree.
template <int dim>
struct CheckpointAccess {
  // Calls visit(name, array, expected count or nothing) for every array of the state.
  template <class Sim, class Visit>
  static void each_array(Sim& s, Visit&& visit) {
    const std::size_t n_nodes = s.mesh_.node_count();
    auto points = [&](const std::string& prefix, auto& p) {
      const std::size_t n = p.size();
      visit(prefix + "position", p.position, n);
      visit(prefix + "velocity", p.velocity, n);
      visit(prefix + "mass", p.mass, n);
      visit(prefix + "volume", p.volume, n);
      visit(prefix + "material", p.material, n);
      visit(prefix + "cell", p.cell, n);
      visit(prefix + "id", p.id, n);
    };
    const std::size_t n_solid = s.solid_.points.size();
    points("solid.", s.solid_.points);
    visit("solid.displacement", s.solid_.points.displacement, n_solid);
    visit("solid.stress", s.solid_.points.stress, n_solid);
    visit("solid.plastic_strain", s.solid_.points.plastic_strain, n_solid);
    // The shape values are refreshed from the position at every relocation; stored, not
    // recomputed, so a point on a cell face keeps the cell and values it had.
    visit("solid.shape", s.solid_.shape, n_solid);
    // The nodal velocities of the last step (grid output leaves them alone): the drag of the
    // next step takes the relative velocity from them (two_phase.cpp).
    visit("solid.node_velocity", s.solid_.node_velocity, n_nodes);
    if (!s.has_liquid_) return;
    const std::size_t n_liquid = s.water_.points.size();
    points("liquid.", s.water_.points);
    visit("liquid.pressure", s.water_.points.pressure, n_liquid);
    visit("liquid.viscous_stress", s.water_.points.viscous_stress, n_liquid);
    visit("liquid.porosity", s.water_.points.porosity, n_liquid);
    visit("liquid.in_flight", s.water_.points.in_flight, n_liquid);
    visit("liquid.shape", s.water_.shape, n_liquid);
    visit("liquid.node_velocity", s.water_.node_velocity, n_nodes);
    // The drag's relative velocity is the pore water's (two_phase.cpp); the mean is what
    // node_liquid_velocity() reports.
    visit("liquid.pore_node_velocity", s.pore_water_velocity_, n_nodes);
    visit("liquid.mean_node_velocity", s.mean_water_velocity_, n_nodes);
    // The pressure projection starts its iterations from its last nodal solution; empty until
    // the first projection.
    visit("liquid.projection_solution", s.projection_.solution, std::nullopt);
  }

  static void write(BinaryOut& out, const Simulation<dim>& s) {
    out.value(s.next_time_step_);
    out.value(s.projection_clock_);
    out.value(static_cast<std::int64_t>(s.projection_count_));
    each_array(s, [&](const std::string& name, const auto& v, std::optional<std::size_t>) {
      out.array(name, v);
    });
    // The boundary forces summed since the stage history's last row (wall_loads.cpp).
    out.value(s.wall_impulse_time_);
    out.array("wall.impulses", flat_wall_impulses(s));
  }

  // Per boundary condition: force (dim values), normal, tangential (dim), pore pressure.
  static constexpr std::size_t kWallValues = 2 * dim + 2;
  static std::vector<double> flat_wall_impulses(const Simulation<dim>& s) {
    std::vector<double> flat;
    std::vector<typename Simulation<dim>::WallImpulse> sums = s.wall_impulse_;
    sums.resize(s.constraints_.size());  // before any stage: none summed yet
    for (const auto& w : sums) {
      for (int d = 0; d < dim; ++d) flat.push_back(w.force(d));
      flat.push_back(w.normal);
      for (int d = 0; d < dim; ++d) flat.push_back(w.tangential(d));
      flat.push_back(w.pore_pressure);
    }
    return flat;
  }

  static void read(BinaryIn& in, Simulation<dim>& s, std::int64_t step_count) {
    s.step_count_ = static_cast<long>(step_count);
    s.next_time_step_ = in.value<double>();
    s.projection_clock_ = in.value<double>();
    s.projection_count_ = static_cast<long>(in.value<std::int64_t>());
    each_array(s, [&](const std::string& name, auto& v, std::optional<std::size_t> expected) {
      in.array(name, v, expected);
    });
    s.wall_impulse_time_ = in.value<double>();
    std::vector<double> flat;
    in.array("wall.impulses", flat, s.constraints_.size() * kWallValues);
    s.wall_impulse_.assign(s.constraints_.size(), {});
    for (std::size_t b = 0, k = 0; b < s.constraints_.size(); ++b) {
      auto& w = s.wall_impulse_[b];
      for (int d = 0; d < dim; ++d) w.force(d) = flat[k++];
      w.normal = flat[k++];
      for (int d = 0; d < dim; ++d) w.tangential(d) = flat[k++];
      w.pore_pressure = flat[k++];
    }
    const std::size_t n_nodes = s.mesh_.node_count();
    auto& p = s.projection_;
    if (p.solution.empty()) return;
    if (p.solution.size() != n_nodes)
      in.damaged("the projection's nodal solution has " + std::to_string(p.solution.size()) +
                 " values for " + std::to_string(n_nodes) + " nodes");
    // The projection's other arrays are work arrays: each projection sizes and fills them
    // (pressure_projection.cpp), so they are not state.
  }

  static void count(const Simulation<dim>& s, CheckpointHeader& h) {
    h.dimension = dim;
    h.solid_points = s.solid_.points.size();
    h.liquid_points = s.water_.points.size();
    h.nodes = s.mesh_.node_count();
    h.step_count = s.step_count_;
    h.threads = s.threads_;
  }
};

}  // namespace detail

template <int dim>
void write_checkpoint(const fs::path& file, const Simulation<dim>& simulation,
                      CheckpointHeader header, const RunRecord& record) {
  header.format_version = kCheckpointFormatVersion;
  header.lituya_version = lituya_version();
  header.commit = lituya_commit();
  header.written = utc_now_iso8601();
  detail::CheckpointAccess<dim>::count(simulation, header);
  fs::create_directories(file.parent_path());
  write_file_atomically(file, [&](std::ostream& stream) {
    BinaryOut out(stream);
    write_header(out, header);
    write_record(out, record);
    detail::CheckpointAccess<dim>::write(out, simulation);
    out.bytes("END!", 4);
    const std::uint64_t checksum = out.checksum();
    stream.write(reinterpret_cast<const char*>(&checksum), sizeof checksum);
  });
}

CheckpointHeader read_checkpoint_header(const fs::path& file) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw InputError(file.string(), 0, "cannot be opened to read the checkpoint");
  BinaryIn in(stream, file);
  return read_header(in);
}

template <int dim>
RunRecord read_checkpoint(const fs::path& file, Simulation<dim>& simulation) {
  std::ifstream stream(file, std::ios::binary);
  if (!stream) throw InputError(file.string(), 0, "cannot be opened to read the checkpoint");
  BinaryIn in(stream, file);
  const CheckpointHeader header = read_header(in);
  CheckpointHeader expected;
  detail::CheckpointAccess<dim>::count(simulation, expected);
  if (header.dimension != dim || header.solid_points != expected.solid_points ||
      header.liquid_points != expected.liquid_points || header.nodes != expected.nodes) {
    std::ostringstream m;
    m << "the checkpoint holds a " << header.dimension << "D state of " << header.solid_points
      << " solid points, " << header.liquid_points << " liquid points and " << header.nodes
      << " nodes; the case has a " << dim << "D mesh of " << expected.nodes << " nodes with "
      << expected.solid_points << " solid and " << expected.liquid_points
      << " liquid points: it belongs to another case";
    in.fail(m.str());
  }
  RunRecord record = read_record(in);
  detail::CheckpointAccess<dim>::read(in, simulation, header.step_count);
  std::array<char, 4> end{};
  in.bytes(end.data(), end.size());
  if (std::string_view(end.data(), end.size()) != "END!")
    in.damaged("no end mark after the last array");
  const std::uint64_t computed = in.checksum();
  const auto stored = in.value<std::uint64_t>();
  if (stored != computed)
    in.damaged("checksum " + hex_hash(stored) + " stored, " + hex_hash(computed) +
               " computed from the bytes");
  if (stream.peek() != std::char_traits<char>::eof()) in.damaged("bytes after the checksum");
  return record;
}

void check_checkpoint(const fs::path& file, const CheckpointHeader& header, const std::string& hash,
                      bool match_whole_case) {
  const std::string where = file.string();
  if (header.lituya_version != lituya_version() || header.commit != lituya_commit())
    throw InputError(where, 0,
                     "written by lituya " + header.lituya_version + " (commit " + header.commit +
                         "), this is lituya " + lituya_version() + " (commit " + lituya_commit() +
                         "): a run goes on only with the build that began it (another build "
                         "may step differently); run the case again with --force");
  const std::string& recorded = match_whole_case ? header.case_hash : header.inputs_hash;
  if (recorded != hash)
    throw InputError(
        where, 0,
        std::string("the case files changed since the checkpoint was written: ") +
            (match_whole_case ? "case files " : "inputs of the stages it ran ") + recorded +
            " then, " + hash +
            " now; the saved state belongs to the old files. Run the case again with --force" +
            (match_whole_case ? " (or, if only later stages changed, --from-stage)" : ""));
}

std::vector<std::string> stage_inputs_hashes(const fs::path& case_folder) {
  const CaseDescription description = read_case(case_folder.string());
  // The data files, as case_files_hash takes them, but without stages.toml: that one enters
  // below, cut to the stages run.
  fs::path folder = case_folder.lexically_normal();
  if (folder.filename().empty() && folder.has_parent_path()) folder = folder.parent_path();
  const std::string data_hash = hash_files(folder, case_data_files(description, folder));

  toml::table stages;
  try {
    stages = toml::parse_file((case_folder / "stages.toml").string());
  } catch (const toml::parse_error& e) {
    throw InputError((case_folder / "stages.toml").string(), 0, std::string(e.description()));
  }
  if (toml::table* solver = stages["solver"].as_table())
    solver->erase("checkpoint_interval_minutes");
  // Probes only observe the state: --from-stage may re-run a stage with probes added or changed
  // (their tables then start at that stage).
  stages.erase("probe");
  std::vector<std::string> hashes;
  for (std::size_t k = 0; k <= description.stages.size(); ++k) {
    toml::table cut = stages;
    if (toml::array* list = cut["stage"].as_array())
      while (list->size() > k) list->pop_back();
    std::ostringstream text;
    text << cut;
    Fnv1a64 h;
    h.add(data_hash);
    h.add(std::string_view("\0", 1));
    h.add(text.str());
    hashes.push_back(hex_hash(h.value()));
  }
  return hashes;
}

fs::path end_of_stage_checkpoint(const fs::path& output_folder, const std::string& stage) {
  return output_folder / kCheckpointFolder / (stage + "_end.checkpoint");
}

fs::path within_stage_checkpoint(const fs::path& output_folder) {
  return output_folder / kCheckpointFolder / "latest.checkpoint";
}

std::optional<fs::path> newest_checkpoint(const fs::path& output_folder) {
  const fs::path folder = output_folder / kCheckpointFolder;
  if (!fs::is_directory(folder)) return std::nullopt;
  std::optional<fs::path> newest;
  std::tuple<std::int64_t, int> newest_key{-1, -1};
  for (const auto& entry : fs::directory_iterator(folder)) {
    if (!entry.is_regular_file() || entry.path().extension() != ".checkpoint") continue;
    const CheckpointHeader h = read_checkpoint_header(entry.path());
    // Further into the run: more steps, or at the same step, a later stage (the end of a
    // stage comes after a checkpoint taken at its last step).
    const std::tuple<std::int64_t, int> key{h.step_count, h.stage};
    if (key > newest_key) {
      newest_key = key;
      newest = entry.path();
    }
  }
  return newest;
}

template void write_checkpoint<2>(const fs::path&, const Simulation<2>&, CheckpointHeader,
                                  const RunRecord&);
template void write_checkpoint<3>(const fs::path&, const Simulation<3>&, CheckpointHeader,
                                  const RunRecord&);
template RunRecord read_checkpoint<2>(const fs::path&, Simulation<2>&);
template RunRecord read_checkpoint<3>(const fs::path&, Simulation<3>&);

}  // namespace lituya::solver
