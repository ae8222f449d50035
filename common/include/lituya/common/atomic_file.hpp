#pragma once
// The one way Lituya writes a file: the bytes go to `file.tmp` in the same folder, and only a
// write that was complete (every write, the flush and the close succeeded) is renamed over
// `file`. A full disk, a read-only file system or a file size limit therefore never replaces a
// good file with an empty or torn one (the previous `.pvd` or `summary.toml` stays whole), and
// the error says which file and why, in the system's words ("No space left on device").
#include <filesystem>
#include <functional>
#include <ostream>
#include <stdexcept>
#include <string_view>

namespace lituya {

// A file that could not be written. Not an input error nor a run error: `lituya` reports it
// as "any other error" (exit code 3).
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Writes what `write` puts into the stream to `file`, atomically (temporary file + rename).
// `write` may stream any amount (a large VTU goes through without a copy in memory). Throws
// WriteError naming `file` and the system's reason; the temporary is removed and `file`, if it
// existed, is unchanged. An exception thrown by `write` leaves `file` unchanged too.
void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write);
void write_file_atomically(const std::filesystem::path& file, std::string_view content);

// Copies `from` to `to` by write_file_atomically (a copy_file interrupted by a full disk would
// leave a torn `to`).
void copy_file_atomically(const std::filesystem::path& from, const std::filesystem::path& to);

// The temporary file `file` is first written to.
std::filesystem::path temporary_file_for(const std::filesystem::path& file);

namespace detail {
// Opens the temporary for writing and returns its file descriptor, or -1 with errno set.
using OpenTemporary = std::function<int(const std::filesystem::path& temporary)>;
// As write_file_atomically, with the temporary opened by `open`. Tests pass an `open` that
// returns a descriptor of /dev/full (every write fails with ENOSPC) to check what a full disk
// does: filling a real disk or making a folder read-only is neither practical nor reliable (root
// writes anyway), and /dev/full itself cannot be the temporary, which is renamed and removed.
void write_file_atomically(const std::filesystem::path& file,
                           const std::function<void(std::ostream&)>& write,
                           const OpenTemporary& open);
}  // namespace detail

}  // namespace lituya
