#include "lituya/verify/runner.hpp"
namespace lituya::verify { bool run_verification(const RunnerOptions&) { return false; } }
