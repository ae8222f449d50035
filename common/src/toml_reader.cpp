#include "lituya/common/toml_reader.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "lituya/common/input_error.hpp"
#include "lituya/common/safe_name.hpp"

namespace lituya {

namespace {
int line_of_node(const toml::node& n, int fallback) {
  const auto& src = n.source();
  return src.begin.line > 0 ? static_cast<int>(src.begin.line) : fallback;
}

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    default:
      return "a date or time";
  }
}

std::optional<double> as_number(const toml::node& n) {
  if (auto v = n.as_floating_point()) return v->get();
  if (auto v = n.as_integer()) return static_cast<double>(v->get());
  return std::nullopt;
}

// How a non-finite TOML float was written, for messages ("-inf", "nan").
std::string non_finite_text(double v) {
  if (std::isnan(v)) return "nan";
  return v > 0 ? "inf" : "-inf";
}

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (size_t i = 0; i < items.size(); ++i) s += (i ? ", \"" : "\"") + items[i] + "\"";
  return s;
}
}  // namespace

TomlTable::TomlTable(const toml::table* table, std::string file, std::string path, int line)
    : table_(table), file_(std::move(file)), path_(std::move(path)), line_(line) {}

bool TomlTable::has(std::string_view key) const {
  return node(key) != nullptr;
}

const toml::node* TomlTable::node(std::string_view key) const {
  used_.insert(std::string(key));
  return table_->get(key);
}

int TomlTable::line_of(std::string_view key) const {
  const toml::node* n = table_->get(key);
  return n ? line_of_node(*n, line_) : line_;
}

std::string TomlTable::where(std::string_view key) const {
  std::string w = path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  return "'" + w + "'";
}

void TomlTable::fail(const std::string& message, std::string_view key) const {
  throw InputError(file_, key.empty() ? line_ : line_of(key), message);
}

const toml::node& TomlTable::required(std::string_view key) const {
  const toml::node* n = node(key);
  if (!n) fail("missing required key " + where(key));
  return *n;
}

double TomlTable::number(std::string_view key) const {
  const toml::node& n = required(key);
  auto v = as_number(n);
  if (!v) fail(where(key) + " must be a number, found " + type_name(n), key);
  if (!std::isfinite(*v))
    fail(where(key) + " = " + non_finite_text(*v) + " is not a finite number", key);
  return *v;
}

double TomlTable::number_or(std::string_view key, double fallback) const {
  return has(key) ? number(key) : fallback;
}

double TomlTable::number_in(std::string_view key, double lo, double hi) const {
  double v = number(key);
  if (!(v >= lo && v <= hi)) {
    std::ostringstream m;
    m << where(key) << " = " << v << " is outside the allowed range [" << lo << ", " << hi << "]";
    fail(m.str(), key);
  }
  return v;
}

double TomlTable::number_in_or(std::string_view key, double lo, double hi, double fallback) const {
  return has(key) ? number_in(key, lo, hi) : fallback;
}

long long TomlTable::integer(std::string_view key) const {
  const toml::node& n = required(key);
  auto v = n.as_integer();
  if (!v) fail(where(key) + " must be an integer, found " + type_name(n), key);
  return v->get();
}

long long TomlTable::integer_or(std::string_view key, long long fallback) const {
  return has(key) ? integer(key) : fallback;
}

bool TomlTable::boolean_or(std::string_view key, bool fallback) const {
  const toml::node* n = node(key);
  if (!n) return fallback;
  auto v = n->as_boolean();
  if (!v) fail(where(key) + " must be true or false, found " + type_name(*n), key);
  return v->get();
}

std::string TomlTable::string(std::string_view key) const {
  const toml::node& n = required(key);
  auto v = n.as_string();
  if (!v) fail(where(key) + " must be a string, found " + type_name(n), key);
  return v->get();
}

std::string TomlTable::string_or(std::string_view key, std::string fallback) const {
  return has(key) ? string(key) : fallback;
}

std::string TomlTable::safe_name(std::string_view key) const {
  std::string v = string(key);
  if (auto problem = safe_name_problem(v))
    fail(where(key) + " = " + quoted_for_message(v) + " is not a valid name: " + *problem + " (" +
             std::string(safe_name_rule()) + ")",
         key);
  return v;
}

std::string TomlTable::choice(std::string_view key, const std::vector<std::string>& choices) const {
  std::string v = string(key);
  for (const auto& c : choices)
    if (c == v) return v;
  fail(where(key) + " = \"" + v + "\" is not one of " + join(choices), key);
}

std::string TomlTable::choice_or(std::string_view key, const std::vector<std::string>& choices,
                                 std::string fallback) const {
  return has(key) ? choice(key, choices) : fallback;
}

std::vector<double> TomlTable::numbers(std::string_view key) const {
  const toml::node& n = required(key);
  auto arr = n.as_array();
  if (!arr) fail(where(key) + " must be an array of numbers, found " + type_name(n), key);
  std::vector<double> out;
  for (const auto& item : *arr) {
    auto v = as_number(item);
    if (!v) fail(where(key) + " must contain only numbers, found " + type_name(item), key);
    // At the element's own line: an array may span several lines.
    if (!std::isfinite(*v))
      throw InputError(
          file_, line_of_node(item, line_of(key)),
          where(key) + " holds " + non_finite_text(*v) + ", which is not a finite number");
    out.push_back(*v);
  }
  return out;
}

std::vector<double> TomlTable::numbers_or(std::string_view key,
                                          std::vector<double> fallback) const {
  return has(key) ? numbers(key) : fallback;
}

std::vector<std::string> TomlTable::strings(std::string_view key) const {
  const toml::node& n = required(key);
  auto arr = n.as_array();
  if (!arr) fail(where(key) + " must be an array of strings, found " + type_name(n), key);
  std::vector<std::string> out;
  for (const auto& item : *arr) {
    auto v = item.as_string();
    if (!v) fail(where(key) + " must contain only strings, found " + type_name(item), key);
    out.push_back(v->get());
  }
  return out;
}

std::vector<std::string> TomlTable::strings_or(std::string_view key,
                                               std::vector<std::string> fallback) const {
  return has(key) ? strings(key) : fallback;
}

TomlTable TomlTable::table(std::string_view key) const {
  const toml::node& n = required(key);
  auto t = n.as_table();
  if (!t) fail(where(key) + " must be a table, found " + type_name(n), key);
  std::string p = path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  return TomlTable(t, file_, p, line_of_node(n, line_));
}

std::optional<TomlTable> TomlTable::optional_table(std::string_view key) const {
  if (!has(key)) return std::nullopt;
  return table(key);
}

std::vector<TomlTable> TomlTable::tables(std::string_view key) const {
  std::vector<TomlTable> out;
  const toml::node* n = node(key);
  if (!n) return out;
  auto arr = n->as_array();
  if (!arr) fail(where(key) + " must be an array of tables ([[" + std::string(key) + "]])", key);
  std::string base = path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  int i = 0;
  for (const auto& item : *arr) {
    auto t = item.as_table();
    if (!t) fail(where(key) + " must contain only tables", key);
    out.emplace_back(t, file_, base + "[" + std::to_string(i++) + "]", line_of_node(item, line_));
  }
  return out;
}

void TomlTable::finish() const {
  for (const auto& [k, v] : *table_) {
    if (!used_.count(k.str())) {
      std::string p = path_.empty() ? "" : " in [" + path_ + "]";
      throw InputError(file_, line_of_node(v, line_),
                       "unknown key '" + std::string(k.str()) + "'" + p +
                           " (a typo? see manuals/file-formats.md for the keys allowed here)");
    }
  }
}

TomlDocument::TomlDocument(const std::filesystem::path& file) : file_(file.string()) {
  std::ifstream in(file);
  if (!in) throw InputError(file_, 0, "cannot open file (does it exist and is it readable?)");
  std::stringstream buffer;
  buffer << in.rdbuf();
  try {
    table_ = std::make_shared<toml::table>(toml::parse(buffer.str(), file_));
  } catch (const toml::parse_error& e) {
    throw InputError(file_, static_cast<int>(e.source().begin.line),
                     "TOML syntax error: " + std::string(e.description()));
  }
}

TomlTable TomlDocument::root() const {
  return TomlTable(table_.get(), file_, "", 1);
}

int TomlDocument::check_header(const TomlTable& root, std::string_view format, int max_version) {
  if (!root.has("format"))
    root.fail("missing header key 'format' (expected format = \"" + std::string(format) + "\")");
  std::string f = root.string("format");
  if (f != format)
    root.fail("this file has format = \"" + f + "\", expected \"" + std::string(format) + "\"",
              "format");
  if (!root.has("version")) root.fail("missing header key 'version' (expected version = 1)");
  long long v = root.integer("version");
  if (v < 1 || v > max_version)
    root.fail("format version " + std::to_string(v) + " is not supported (this Lituya reads " +
                  std::string(format) + " versions 1 to " + std::to_string(max_version) + ")",
              "version");
  return static_cast<int>(v);
}

}  // namespace lituya
