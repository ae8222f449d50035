#include "lituya/common/output_folder.hpp"

#include "lituya/common/input_error.hpp"

namespace lituya {

void prepare_output_folder(const std::filesystem::path& folder, bool overwrite) {
  namespace fs = std::filesystem;
  std::error_code error;  // e.g. a symbolic link loop: an input error, not a crash
  const fs::file_status status = fs::status(folder, error);
  if (error && status.type() != fs::file_type::not_found)
    throw InputError(
        folder.string(), 0,
        "cannot be used as the output folder (" + error.message() + "); choose another output");
  if (fs::exists(status)) {
    if (!fs::is_directory(folder))
      throw InputError(folder.string(), 0, "exists and is not a folder; choose another output");
    if (!fs::is_empty(folder) && !overwrite)
      throw InputError(folder.string(), 0,
                       "this folder already holds files (an earlier run?); nothing was "
                       "overwritten. Pass --force to overwrite it, or choose another folder");
  }
  fs::create_directories(folder);
}

}  // namespace lituya
