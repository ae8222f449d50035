#pragma once
// What produced a result: the Lituya version, the git commit of the sources it was built from
// and the time of the run. Results are handed on and compared months later; log.txt,
// summary.toml and the verification report record these so a result can be traced to the
// code and the inputs that made it (the inputs by content_hash.hpp).
//
// The version and commit are generated into common/ (common/version.cmake, at every build),
// not into the CLI, so that the solver and the verification runner can record them without
// depending on the command-line program.
#include <chrono>
#include <string>

namespace lituya {

// The project version, e.g. "0.1.0".
const char* lituya_version();
// `git describe --always` of the sources ("-dirty" with uncommitted changes to tracked
// files), or "unknown" when built outside a git checkout.
const char* lituya_commit();
// "lituya 0.1.0 (commit abc1234)": the line `lituya --version` prints.
std::string version_line();

// `time` in UTC, ISO 8601 to the second: "2024-05-01T12:34:56Z".
std::string utc_iso8601(std::chrono::system_clock::time_point time);
// Now, as utc_iso8601.
std::string utc_now_iso8601();

}  // namespace lituya
