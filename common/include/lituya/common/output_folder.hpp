#pragma once
// Nothing a user wrote, nor an earlier run's results, is overwritten without being asked:
// a folder that already holds files is refused unless the user passed --force.
#include <filesystem>

namespace lituya {

// Creates `folder` (and parents). If it exists and is not empty, throws InputError unless
// `overwrite` is true.
void prepare_output_folder(const std::filesystem::path& folder, bool overwrite);

}  // namespace lituya
