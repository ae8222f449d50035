#include "lituya/common/output_folder.hpp"

#include "lituya/common/input_error.hpp"

namespace lituya {

void prepare_output_folder(const std::filesystem::path& folder, bool overwrite) {
  namespace fs = std::filesystem;
  if (fs::exists(folder)) {
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
