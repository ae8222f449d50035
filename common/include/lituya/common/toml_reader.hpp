#pragma once
// Validated reading of the TOML files users write (scene) and Lituya writes (materials,
// stages, post). Every getter names the file, the line and what was expected when the value
// is missing or of the wrong type, and `finish()` rejects keys that nobody read, so a typo
// such as `frction_angle` is an error instead of a silently ignored setting.
// TOML allows the floats inf, -inf and nan; no Lituya key has a use for them and they would
// only surface as a non-finite state later (gravity = [0, -inf] passed `lituya pre`), so the
// number getters refuse them for every key.
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <toml++/toml.h>

namespace lituya {

class TomlTable {
 public:
  TomlTable(const toml::table* table, std::string file, std::string path, int line);

  bool has(std::string_view key) const;
  int line() const { return line_; }
  int line_of(std::string_view key) const;  // line of the key, or of the table if absent
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

  // A finite number (an integer is accepted too).
  double number(std::string_view key) const;
  double number_or(std::string_view key, double fallback) const;
  // A number that must lie in [lo, hi] (inclusive); `what` says what it is for the message.
  double number_in(std::string_view key, double lo, double hi) const;
  double number_in_or(std::string_view key, double lo, double hi, double fallback) const;
  long long integer(std::string_view key) const;
  long long integer_or(std::string_view key, long long fallback) const;
  bool boolean_or(std::string_view key, bool fallback) const;
  std::string string(std::string_view key) const;
  std::string string_or(std::string_view key, std::string fallback) const;
  // A name that becomes part of a file name or an identifier in other files (stage and
  // material names): a string that follows the safe alphabet of safe_name.hpp.
  std::string safe_name(std::string_view key) const;
  // A string that must be one of `choices`.
  std::string choice(std::string_view key, const std::vector<std::string>& choices) const;
  std::string choice_or(std::string_view key, const std::vector<std::string>& choices,
                        std::string fallback) const;
  // An array of finite numbers.
  std::vector<double> numbers(std::string_view key) const;
  std::vector<double> numbers_or(std::string_view key, std::vector<double> fallback) const;
  std::vector<std::string> strings(std::string_view key) const;
  std::vector<std::string> strings_or(std::string_view key,
                                      std::vector<std::string> fallback) const;
  TomlTable table(std::string_view key) const;
  std::optional<TomlTable> optional_table(std::string_view key) const;
  // `[[key]]` arrays of tables; empty when absent.
  std::vector<TomlTable> tables(std::string_view key) const;

  // Throws InputError naming the first key of this table that no getter asked for.
  void finish() const;
  // Throws InputError at this table's line (or at `key`'s line when given).
  [[noreturn]] void fail(const std::string& message, std::string_view key = {}) const;

 private:
  const toml::node* node(std::string_view key) const;
  const toml::node& required(std::string_view key) const;
  std::string where(std::string_view key) const;

  const toml::table* table_;
  std::string file_;
  std::string path_;  // e.g. "stage[2]" for messages
  int line_;
  mutable std::set<std::string, std::less<>> used_;
};

// A parsed TOML file that owns its table.
class TomlDocument {
 public:
  // Parses `file`; syntax errors and missing files become InputError with file and line.
  explicit TomlDocument(const std::filesystem::path& file);
  TomlTable root() const;
  // Checks the header keys `format = "<format>"` and `version = <n>` (n <= max_version) and
  // marks them read; returns the version.
  static int check_header(const TomlTable& root, std::string_view format, int max_version);
  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::shared_ptr<toml::table> table_;
};

}  // namespace lituya
