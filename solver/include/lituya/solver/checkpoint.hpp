#pragma once
// Checkpoints: the whole state of a run between two steps, written so that a run killed,
// stopped or crashed hours in can go on from it (`lituya solve CASE --resume`), and so that a
// later stage can be re-run from the end state of the one before (`--from-stage NAME`).
//
// What is in one (the format is in manuals/file-formats.md, "Checkpoints"):
// - a header: magic, format version, the Lituya version and commit that wrote it, the hash of
//   the case files (solve.hpp's case_files_hash) and of the inputs of the stages run so far,
//   the dimension, the point and node counts, the step count and where in which stage it was
//   taken;
// - the run's record: the start date, the reports of the stages already run, and each .pvd
//   series with its entries (the resumed run's series list the earlier frames);
// - every array of the solid and liquid points (raw IEEE doubles: a resumed run continues
//   bit for bit), the shape values of each point in its cell, and the nodal state that carries
//   from one step to the next: the nodal velocities (the drag of the next step uses them) and
//   the warm start of the pressure projection;
// - an FNV-1a 64 checksum of all the bytes before it, so a torn or damaged file is refused.
//
// A checkpoint continues a run only with the build and the case files that wrote it; anything
// else is refused with an InputError that says what differs.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lituya/solver/output_writer.hpp"
#include "lituya/solver/simulation.hpp"

namespace lituya::solver {

inline constexpr std::uint32_t kCheckpointFormatVersion = 5;
// The folder, under the output folder, that holds a run's checkpoints.
inline constexpr const char* kCheckpointFolder = "checkpoints";

// What a checkpoint says about itself; read without the arrays (read_checkpoint_header).
struct CheckpointHeader {
  std::uint32_t format_version = kCheckpointFormatVersion;
  std::string lituya_version, commit;
  std::string case_hash;    // case_files_hash of the case that wrote it
  std::string inputs_hash;  // stage_inputs_hash(case, stage): what the state depends on
  std::string started;      // UTC, ISO 8601: when the run began (not a resumption of it)
  std::string written;      // UTC, ISO 8601
  std::string reason;       // "end of stage 'gravity'", "every 30 minutes", "stopped by SIGINT"
  int dimension = 2;
  int threads = 1;  // a run repeats bit for bit only with the same number of threads
  std::uint64_t solid_points = 0, liquid_points = 0, nodes = 0;
  std::int64_t step_count = 0;
  // The stage the run goes on with (its index in stages.toml) and, when the checkpoint was
  // taken within it, how far it had got; at the end of a stage, the next stage from its start.
  int stage = 0;
  std::optional<StageProgress> within_stage;
};

// What the run had done before the checkpoint, beyond the simulation's state.
struct RunRecord {
  std::vector<StageReport> reports;  // the stages completed
  std::vector<SeriesRecord> series;  // the .pvd series and their entries
};

// Writes the checkpoint atomically (write_file_atomically): a kill or a full disk during the
// write leaves the previous checkpoint of that name whole. `header`'s counts, dimension and
// step count, version, commit and date are filled in here.
template <int dim>
void write_checkpoint(const std::filesystem::path& file, const Simulation<dim>& simulation,
                      CheckpointHeader header, const RunRecord& record);

// Reads the header only. Throws InputError naming the file for a file that is not a Lituya
// checkpoint (wrong magic), of another format version, or cut short.
CheckpointHeader read_checkpoint_header(const std::filesystem::path& file);

// Reads the whole checkpoint into `simulation`, which must have been built from the same case
// (the counts are checked, the hashes are the caller's to check with check_checkpoint), and
// returns the run's record. Throws InputError for a file cut short or damaged (checksum).
template <int dim>
RunRecord read_checkpoint(const std::filesystem::path& file, Simulation<dim>& simulation);

// Refuses (InputError naming `file`) a checkpoint that another Lituya version or commit wrote,
// or whose hash differs from `inputs_hash` ("the case files changed since the checkpoint was
// written"). `match_whole_case`: compare the checkpoint's case_hash (--resume), else its
// inputs_hash (--from-stage: the later stages may have changed).
void check_checkpoint(const std::filesystem::path& file, const CheckpointHeader& header,
                      const std::string& hash, bool match_whole_case);

// Element k: the hash of what the state after the first k stages depends on (k = 0 to the
// number of stages): the geometry, points, materials and liquid points files, and stages.toml
// without the stages from index k on (and without checkpoint_interval_minutes, which changes
// nothing in the state). Two cases with the same element k reach the same state after their
// first k stages, so the end-of-stage checkpoint of one can start stage k of the other.
std::vector<std::string> stage_inputs_hashes(const std::filesystem::path& case_folder);

// The file names of a run's checkpoints in `output_folder`/checkpoints: the end-of-stage one
// of each stage, and the latest one taken within a stage (every N minutes, or on a stop).
std::filesystem::path end_of_stage_checkpoint(const std::filesystem::path& output_folder,
                                              const std::string& stage);
std::filesystem::path within_stage_checkpoint(const std::filesystem::path& output_folder);

// The newest checkpoint in `output_folder`/checkpoints (the one furthest into the run), or
// nothing when there is none. Throws InputError for a file there that is not a readable
// checkpoint (its header): the newest state might be in it.
std::optional<std::filesystem::path> newest_checkpoint(const std::filesystem::path& output_folder);

}  // namespace lituya::solver
