#include "lituya/sweep/definition.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

#include <toml++/toml.h>

#include "lituya/common/input_error.hpp"
#include "lituya/common/toml_reader.hpp"
#include "lituya/sweep/repeats.hpp"

namespace lituya::sweep {

namespace fs = std::filesystem;

namespace {

constexpr size_t kMaxValues = 1000;

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::optional<double> number(const std::string& s) {
  if (s.empty()) return std::nullopt;
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

// A range value, without the roundoff of START + i STEP (0.30000000000000004).
std::string range_value(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.12g", v);
  return text;
}

std::string shortest(double v) {
  char buffer[64];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

}  // namespace

std::vector<std::string> split_list(const std::string& text) {
  std::vector<std::string> items;
  std::string item;
  std::istringstream in(text);
  while (std::getline(in, item, ','))
    if (!trim(item).empty()) items.push_back(trim(item));
  return items;
}

std::vector<std::string> parse_value_list(const std::string& text) {
  std::vector<std::string> values;
  std::string item;
  std::istringstream in(text);
  bool any = false;
  while (std::getline(in, item, ',')) {
    any = true;
    item = trim(item);
    if (item.empty())
      throw InputError("--values", 0, "empty value in \"" + text + "\" (write V1,V2,...)");
    // START:STOP:STEP when the three parts are numbers; otherwise a value with colons.
    std::vector<std::string> parts;
    std::string part;
    std::istringstream range(item);
    while (std::getline(range, part, ':')) parts.push_back(trim(part));
    std::optional<double> start, stop, step;
    if (parts.size() == 3)
      start = number(parts[0]), stop = number(parts[1]), step = number(parts[2]);
    if (start && stop && step) {
      if (*step == 0 || (*stop - *start) * *step < 0)
        throw InputError(
            "--values", 0,
            "range \"" + item + "\": STEP must be non-zero and lead from START to STOP");
      const double count = std::floor((*stop - *start) / *step + 1e-9) + 1;
      if (count > static_cast<double>(kMaxValues))
        throw InputError("--values", 0, "range \"" + item + "\" gives more than 1000 values");
      for (long i = 0; i < static_cast<long>(count); ++i)
        values.push_back(range_value(*start + static_cast<double>(i) * *step));
    } else {
      values.push_back(item);
    }
    if (values.size() > kMaxValues) throw InputError("--values", 0, "more than 1000 values");
  }
  if (!any || values.empty()) throw InputError("--values", 0, "no values given (write V1,V2,...)");
  return values;
}

bool is_sweep_file(const fs::path& file) {
  try {
    const toml::table t = toml::parse_file(file.string());
    const auto* format = t.get_as<std::string>("format");
    return format && format->get() == "lituya-sweep";
  } catch (const std::exception&) {
    return false;
  }
}

namespace {

std::string values_text(size_t n) {
  return std::to_string(n) + (n == 1 ? " value" : " values");
}

}  // namespace

std::string combination_name(Combination combination) {
  return combination == Combination::kZip ? "zip" : "grid";
}

std::vector<std::vector<size_t>> combinations(const SweepDefinition& d) {
  const std::string where = d.source.empty() ? "--parameter" : d.source.string();
  auto fail = [&](int line, const std::string& message) { throw InputError(where, line, message); };
  if (d.parameters.empty()) fail(0, "no parameter to sweep");
  for (size_t p = 0; p < d.parameters.size(); ++p) {
    const SweepParameter& parameter = d.parameters[p];
    if (parameter.values.empty())
      fail(parameter.line, "'" + parameter.key + "' has no values to sweep");
    for (size_t q = 0; q < p; ++q)
      if (d.parameters[q].key == parameter.key)
        fail(parameter.line,
             "'" + parameter.key + "' is given twice" +
                 (d.parameters[q].line > 0
                      ? " (first at line " + std::to_string(d.parameters[q].line) + ")"
                      : std::string()));
  }
  std::vector<std::vector<size_t>> runs;
  if (d.combination == Combination::kZip) {
    const SweepParameter& first = d.parameters.front();
    for (const SweepParameter& parameter : d.parameters)
      if (parameter.values.size() != first.values.size())
        fail(parameter.line, (d.source.empty() ? "--combine zip" : "combine = \"zip\"") +
                                 std::string(" pairs the i-th values of every key, but '") +
                                 parameter.key + "' has " + values_text(parameter.values.size()) +
                                 " and '" + first.key + "' has " +
                                 values_text(first.values.size()) + " (" +
                                 (d.source.empty() ? "--combine grid" : "combine = \"grid\"") +
                                 " makes every combination)");
    for (size_t i = 0; i < first.values.size(); ++i) runs.emplace_back(d.parameters.size(), i);
    return runs;
  }
  double count = 1;
  for (const SweepParameter& parameter : d.parameters)
    count *= static_cast<double>(parameter.values.size());
  if (count > static_cast<double>(kMaxRuns)) {
    std::string sizes;
    for (const SweepParameter& parameter : d.parameters)
      sizes += (sizes.empty() ? "" : " x ") + std::to_string(parameter.values.size());
    fail(d.parameters.back().line, "the grid of every combination has " + sizes + " = " +
                                       range_value(count) + " runs, more than " +
                                       std::to_string(kMaxRuns));
  }
  // The first key varies slowest, as nested loops written in the order of the keys.
  std::vector<size_t> index(d.parameters.size(), 0);
  for (;;) {
    runs.push_back(index);
    size_t p = d.parameters.size();
    while (p > 0) {
      --p;
      if (++index[p] < d.parameters[p].values.size()) break;
      index[p] = 0;
      if (p == 0) return runs;
    }
  }
}

namespace {

// The values of a sweep file's `values` array (numbers, strings or booleans) as text.
std::vector<std::string> read_values(const TomlTable& table, const toml::node* node) {
  const toml::array* values = node ? node->as_array() : nullptr;
  if (!values || values->empty())
    table.fail("'values' must be a non-empty array of numbers, strings or booleans", "values");
  std::vector<std::string> out;
  for (const toml::node& v : *values) {
    if (auto i = v.value_exact<int64_t>())
      out.push_back(std::to_string(*i));
    else if (auto x = v.value_exact<double>())
      out.push_back(shortest(*x));
    else if (auto b = v.value_exact<bool>())
      out.push_back(*b ? "true" : "false");
    else if (auto str = v.value_exact<std::string>())
      out.push_back(*str);
    else
      table.fail("'values' must hold numbers, strings or booleans only", "values");
  }
  if (out.size() > kMaxValues) table.fail("'values' holds more than 1000 values", "values");
  return out;
}

}  // namespace

SweepDefinition read_sweep_file(const fs::path& file) {
  const TomlDocument document(file);
  const TomlTable root = document.root();
  TomlDocument::check_header(root, "lituya-sweep", 1);
  SweepDefinition d;
  d.source = file;
  const fs::path folder = file.parent_path();
  d.scene = folder / root.string("scene");
  // The values may be numbers, strings or booleans: read them from the raw table.
  const toml::table raw = toml::parse_file(file.string());
  const toml::node* parameter = raw.get("parameter");
  if (!parameter)
    root.fail(
        "missing required key 'parameter' (the key to vary, or one [[parameter]] entry per key)");
  if (parameter->is_string()) {
    SweepParameter p;
    p.key = root.string("parameter");
    p.line = root.line_of("parameter");
    if (!root.has("values"))
      root.fail("missing required key 'values' (the values of the parameter)");
    p.values = read_values(root, raw.get("values"));
    d.parameters.push_back(p);
  } else if (parameter->is_array_of_tables()) {
    if (root.has("values"))
      root.fail("'values' belongs in each [[parameter]] entry, next to its 'key'", "values");
    const std::vector<TomlTable> entries = root.tables("parameter");
    const toml::array& raw_entries = *parameter->as_array();
    for (size_t i = 0; i < entries.size(); ++i) {
      SweepParameter p;
      p.key = entries[i].string("key");
      p.line = entries[i].line();
      if (!entries[i].has("values"))
        entries[i].fail("missing required key 'values' (the values of '" + p.key + "')");
      p.values = read_values(entries[i], raw_entries[i].as_table()->get("values"));
      entries[i].finish();
      d.parameters.push_back(p);
    }
  } else {
    root.fail(
        "'parameter' must be a key (parameter = \"material.sand.friction_angle\") or "
        "[[parameter]] entries with 'key' and 'values'",
        "parameter");
  }
  d.combination = root.choice_or("combine", {"grid", "zip"}, "grid") == "zip" ? Combination::kZip
                                                                              : Combination::kGrid;
  d.measures = root.strings_or("measures", {});
  if (root.has("output")) d.output = folder / root.string("output");
  if (root.has("repeats")) {
    d.repeats_line = root.line_of("repeats");
    d.repeats = static_cast<int>(root.integer_or("repeats", 1));
    const std::string range = repeats_range_error(d.repeats);
    if (!range.empty()) root.fail("'repeats' " + range, "repeats");
  }
  if (root.has("repeat_by"))
    d.repeat_by = *repeat_by_from_name(root.choice_or(
        "repeat_by", {repeat_by_name(RepeatBy::kCourant), repeat_by_name(RepeatBy::kMesh)}, ""));
  root.finish();
  combinations(d);  // zip lengths, repeated keys and the number of runs, at their lines
  return d;
}

std::string repeat_by_name(RepeatBy by) {
  return by == RepeatBy::kMesh ? "mesh" : "courant";
}

RepeatBy repeat_by_for(const SweepDefinition& definition) {
  if (definition.repeat_by) return *definition.repeat_by;
  for (const SweepParameter& parameter : definition.parameters)
    if (parameter.key == kCellSizeKey) return RepeatBy::kMesh;
  return RepeatBy::kCourant;
}

std::optional<RepeatBy> repeat_by_from_name(const std::string& name) {
  for (RepeatBy by : {RepeatBy::kCourant, RepeatBy::kMesh})
    if (name == repeat_by_name(by)) return by;
  return std::nullopt;
}

fs::path default_output(const SweepDefinition& d) {
  if (!d.output.empty()) return d.output;
  if (!d.source.empty()) {
    fs::path out = d.source;
    out.replace_extension();
    return out;
  }
  std::string keys;
  for (const SweepParameter& p : d.parameters) keys += (keys.empty() ? "" : "+") + p.key;
  return d.scene.parent_path() / ("sweep_" + keys);
}

std::string sweep_file_text(const SweepDefinition& d,
                            const std::vector<std::vector<std::string>>& literals,
                            const std::vector<std::string>& measure_names) {
  auto quoted = [](const std::string& s) {
    std::ostringstream q;
    q << toml::value<std::string>(s);
    return q.str();
  };
  auto list = [](const std::vector<std::string>& items) {
    std::string text = "[";
    for (size_t i = 0; i < items.size(); ++i) text += (i ? ", " : "") + items[i];
    return text + "]";
  };
  std::string text =
      "# Written by `lituya sweep`. Run the same sweep again with: lituya sweep <this file> -o "
      "DIR\n"
      "format = \"lituya-sweep\"\nversion = 1\n";
  text += "scene = " + quoted(fs::absolute(d.scene).lexically_normal().string()) + "\n";
  if (d.repeats > 1) text += "repeats = " + std::to_string(d.repeats) + "\n";
  // Written whenever there are repeats, so that the file runs the same sweep whatever the
  // default of a later version.
  if (d.repeats > 1) text += "repeat_by = " + quoted(repeat_by_name(repeat_by_for(d))) + "\n";
  std::vector<std::string> measures;
  for (const std::string& m : measure_names) measures.push_back(quoted(m));
  if (d.parameters.size() == 1) {
    text += "parameter = " + quoted(d.parameters[0].key) + "\n";
    text += "values = " + list(literals.at(0)) + "\n";
    text += "measures = " + list(measures) + "\n";
    return text;
  }
  text += "combine = " + quoted(combination_name(d.combination)) + "\n";
  text += "measures = " + list(measures) + "\n";
  for (size_t p = 0; p < d.parameters.size(); ++p)
    text += "\n[[parameter]]\nkey = " + quoted(d.parameters[p].key) +
            "\nvalues = " + list(literals.at(p)) + "\n";
  return text;
}

}  // namespace lituya::sweep
