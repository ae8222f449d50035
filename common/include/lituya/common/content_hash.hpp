#pragma once
// A fingerprint of input files, recorded with every result (summary.toml, log.txt, the
// verification report) so that two results can be told to come from the same inputs or not,
// and so that a later checkpoint can refuse a state that belongs to other inputs.
//
// FNV-1a 64 (Fowler, Noll, Vo): simple, fast enough for case files of hundreds of MB, and the
// same on every platform. It detects changes; it is not meant to resist deliberate
// collisions, which nothing here needs.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace lituya {

class Fnv1a64 {
 public:
  void add(std::string_view bytes);
  // The file's bytes; throws std::runtime_error naming the file when it cannot be read.
  void add_file(const std::filesystem::path& file);
  std::uint64_t value() const { return state_; }

 private:
  std::uint64_t state_ = 14695981039346656037ull;  // the FNV 64-bit offset basis
};

// The FNV-1a 64 hash of `bytes`.
std::uint64_t fnv1a64(std::string_view bytes);

// The hash of the files `relative` under `folder`, taken in sorted order of their relative
// paths (so the order the caller lists them in does not matter). Each file contributes its
// relative path and its size as well as its bytes, so renaming a file or moving bytes from one
// file to the next changes the hash. Returns "fnv1a64:" and 16 hexadecimal digits.
std::string hash_files(const std::filesystem::path& folder,
                       std::vector<std::filesystem::path> relative);

// hash_files of every regular file under `folder`, recursively.
std::string hash_folder(const std::filesystem::path& folder);

}  // namespace lituya
