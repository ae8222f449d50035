#include "lituya/common/content_hash.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace lituya {

namespace fs = std::filesystem;

void Fnv1a64::add(std::string_view bytes) {
  constexpr std::uint64_t kPrime = 1099511628211ull;
  for (const char c : bytes) {
    state_ ^= static_cast<unsigned char>(c);
    state_ *= kPrime;
  }
}

void Fnv1a64::add_file(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot be read to hash the case files");
  std::array<char, 1 << 16> buffer;
  while (in) {
    in.read(buffer.data(), buffer.size());
    add(std::string_view(buffer.data(), static_cast<std::size_t>(in.gcount())));
  }
  if (in.bad()) throw std::runtime_error(file.string() + ": read error while hashing");
}

std::uint64_t fnv1a64(std::string_view bytes) {
  Fnv1a64 h;
  h.add(bytes);
  return h.value();
}

std::string hash_files(const fs::path& folder, std::vector<fs::path> relative) {
  // generic_string: the same order and bytes whatever the platform's separator.
  std::sort(relative.begin(), relative.end(), [](const fs::path& a, const fs::path& b) {
    return a.generic_string() < b.generic_string();
  });
  Fnv1a64 h;
  for (const fs::path& name : relative) {
    const fs::path file = folder / name;
    const std::string text = name.generic_string();
    h.add(std::string_view(text.c_str(), text.size() + 1));  // with its '\0': a clear boundary
    std::error_code error;
    const std::uintmax_t size = fs::file_size(file, error);
    if (error) throw std::runtime_error(file.string() + ": " + error.message());
    std::array<char, 8> size_bytes;
    for (int i = 0; i < 8; ++i) size_bytes[i] = static_cast<char>((size >> (8 * i)) & 0xff);
    h.add(std::string_view(size_bytes.data(), size_bytes.size()));
    h.add_file(file);
  }
  char text[32];
  std::snprintf(text, sizeof text, "fnv1a64:%016llx", static_cast<unsigned long long>(h.value()));
  return text;
}

std::string hash_folder(const fs::path& folder) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    if (entry.is_regular_file()) files.push_back(fs::relative(entry.path(), folder));
  return hash_files(folder, std::move(files));
}

}  // namespace lituya
