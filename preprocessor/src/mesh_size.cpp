#include "lituya/pre/mesh_size.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

namespace lituya::pre {

MeshSizeEstimate estimate_mesh_size(double measure, int dimension, double cell_size,
                                    int points_per_cell, bool crossed) {
  const double triangle = crossed ? 0.25 : std::sqrt(3.0) / 4;
  const double cell_measure =
      dimension == 2 ? triangle * cell_size * cell_size : cell_size * cell_size * cell_size / 4.7;
  MeshSizeEstimate e;
  e.cells = measure / cell_measure;
  e.points = e.cells * points_per_cell;
  e.bytes =
      e.cells * kBytesPerCell + e.points * (dimension == 2 ? kBytesPerPoint2D : kBytesPerPoint3D);
  return e;
}

namespace {

// The value in kB of `key` in /proc/meminfo, as bytes; 0 when absent (not Linux).
double meminfo_bytes(const std::string& key) {
  std::ifstream in("/proc/meminfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(key + ":", 0) != 0) continue;
    std::istringstream fields(line.substr(key.size() + 1));
    double kb = 0;
    if (fields >> kb) return kb * 1024;
  }
  return 0;
}

// The cgroup v2 (or v1) memory limit of this process, in bytes; infinity when unlimited or
// unknown. On a shared machine or in a container this, not the machine's memory, is what
// the kernel enforces.
double cgroup_limit_bytes() {
  for (const char* file :
       {"/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"}) {
    std::ifstream in(file);
    std::string text;
    if (!(in >> text) || text == "max") continue;
    try {
      const double limit = std::stod(text);
      // cgroup v1 writes "no limit" as a huge number near 2^63.
      if (limit > 0 && limit < 1e18) return limit;
    } catch (const std::exception&) {
      // Not a number: treated as no limit.
    }
  }
  return std::numeric_limits<double>::infinity();
}

}  // namespace

double available_memory_bytes() {
  double bytes = meminfo_bytes("MemAvailable");
  if (bytes <= 0) {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages > 0 && page > 0) bytes = static_cast<double>(pages) * static_cast<double>(page);
  }
  if (bytes <= 0) bytes = std::numeric_limits<double>::infinity();  // unknown: no check
  return std::min(bytes, cgroup_limit_bytes());
}

}  // namespace lituya::pre
