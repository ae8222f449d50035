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

SweepDefinition read_sweep_file(const fs::path& file) {
  const TomlDocument document(file);
  const TomlTable root = document.root();
  TomlDocument::check_header(root, "lituya-sweep", 1);
  SweepDefinition d;
  d.source = file;
  const fs::path folder = file.parent_path();
  d.scene = folder / root.string("scene");
  d.parameter = root.string("parameter");
  if (!root.has("values")) root.fail("missing required key 'values' (the values of the parameter)");
  // The values may be numbers, strings or booleans: read them from the raw table.
  const toml::table raw = toml::parse_file(file.string());
  const toml::array* values = raw.get_as<toml::array>("values");
  if (!values || values->empty())
    root.fail("'values' must be a non-empty array of numbers, strings or booleans", "values");
  for (const toml::node& v : *values) {
    if (auto i = v.value_exact<int64_t>())
      d.values.push_back(std::to_string(*i));
    else if (auto x = v.value_exact<double>())
      d.values.push_back(shortest(*x));
    else if (auto b = v.value_exact<bool>())
      d.values.push_back(*b ? "true" : "false");
    else if (auto s = v.value_exact<std::string>())
      d.values.push_back(*s);
    else
      root.fail("'values' must hold numbers, strings or booleans only", "values");
  }
  if (d.values.size() > kMaxValues) root.fail("'values' holds more than 1000 values", "values");
  d.measures = root.strings_or("measures", {});
  if (root.has("output")) d.output = folder / root.string("output");
  root.finish();
  return d;
}

fs::path default_output(const SweepDefinition& d) {
  if (!d.output.empty()) return d.output;
  if (!d.source.empty()) {
    fs::path out = d.source;
    out.replace_extension();
    return out;
  }
  return d.scene.parent_path() / ("sweep_" + d.parameter);
}

std::string sweep_file_text(const SweepDefinition& d, const std::vector<std::string>& literals,
                            const std::vector<std::string>& measure_names) {
  auto quoted = [](const std::string& s) {
    std::ostringstream q;
    q << toml::value<std::string>(s);
    return q.str();
  };
  std::string text =
      "# Written by `lituya sweep`. Run the same sweep again with: lituya sweep <this file> -o "
      "DIR\n"
      "format = \"lituya-sweep\"\nversion = 1\n";
  text += "scene = " + quoted(fs::absolute(d.scene).lexically_normal().string()) + "\n";
  text += "parameter = " + quoted(d.parameter) + "\n";
  text += "values = [";
  for (size_t i = 0; i < literals.size(); ++i) text += (i ? ", " : "") + literals[i];
  text += "]\nmeasures = [";
  for (size_t i = 0; i < measure_names.size(); ++i)
    text += (i ? ", " : "") + quoted(measure_names[i]);
  text += "]\n";
  return text;
}

}  // namespace lituya::sweep
