#include "lituya/sweep/scene_edit.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <sstream>

#include "lituya/common/input_error.hpp"
#include "lituya/common/quoted_list.hpp"

namespace lituya::sweep {

namespace fs = std::filesystem;

namespace {

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(key);
  while (std::getline(in, part, '.')) parts.push_back(part);
  if (!key.empty() && key.back() == '.') parts.push_back("");
  return parts;
}

std::string trim(const std::string& s) {
  const size_t b = s.find_first_not_of(" \t");
  if (b == std::string::npos) return "";
  return s.substr(b, s.find_last_not_of(" \t") - b + 1);
}

std::vector<std::string> keys_of(const toml::table& table) {
  std::vector<std::string> keys;
  for (const auto& [k, v] : table) keys.emplace_back(k.str());
  return keys;
}

int line_of(const toml::node& node, int fallback = 0) {
  const int line = static_cast<int>(node.source().begin.line);
  return line > 0 ? line : fallback;
}

bool is_scalar(const toml::node& n) {
  return n.is_integer() || n.is_floating_point() || n.is_string() || n.is_boolean();
}

ValueType type_of(const toml::node& n) {
  if (n.is_integer()) return ValueType::kInteger;
  if (n.is_floating_point()) return ValueType::kNumber;
  if (n.is_boolean()) return ValueType::kBoolean;
  return ValueType::kString;
}

std::optional<size_t> as_index(const std::string& s) {
  if (s.empty() || s.size() > 9 ||
      !std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); }))
    return {};
  return static_cast<size_t>(std::stoul(s));
}

// The result of walking a key through a parsed scene.
struct Walk {
  const toml::node* value = nullptr;    // the scalar, when present
  const toml::table* parent = nullptr;  // the table that holds or will hold the last key
  bool create_table = false;            // a missing top-level table (two-part key)
  std::string where;                    // the parent, for messages
  int line = 0;
};

// Walks `key` through `root`. `fail` receives (line, message) and must throw.
template <class Fail>
Walk walk(const toml::table& root, const std::string& key, Fail fail) {
  const std::vector<std::string> parts = split_key(key);
  if (parts.empty() || std::any_of(parts.begin(), parts.end(), [](auto& p) { return p.empty(); }))
    fail(0, "'" + key + "' is not a key path (write it like material.beads.friction_angle)");
  Walk w;
  const toml::node* node = &root;
  w.where = "the top level";
  w.line = 1;
  std::string path;  // walked so far, for messages
  for (size_t i = 0; i < parts.size(); ++i) {
    const std::string& part = parts[i];
    const bool last = i + 1 == parts.size();
    bool picked_entry = false;
    if (const toml::table* table = node->as_table()) {
      const toml::node* child = table->get(part);
      if (!child) {
        if (last) {
          w.parent = table;
          return w;
        }
        if (table == &root && i + 2 == parts.size()) {
          w.parent = table;
          w.create_table = true;
          w.where = "[" + part + "] (not in the scene)";
          return w;
        }
        fail(w.line, "'" + key + "': " + w.where + " has no key '" + part +
                         "' (it has: " + quoted_list(keys_of(*table)) + ")");
      }
      node = child;
    } else if (const toml::array* array = node->as_array()) {
      if (!array->empty()) w.line = line_of(*array->get(0), w.line);
      const bool of_tables = !array->empty() && array->is_array_of_tables();
      const toml::node* chosen = nullptr;
      std::string how;
      if (of_tables) {
        for (const char* selector : {"name", "group"}) {
          std::vector<const toml::node*> matches;
          for (const toml::node& entry : *array) {
            const auto* value = entry.as_table()->get_as<std::string>(selector);
            if (value && value->get() == part) matches.push_back(&entry);
          }
          if (matches.size() > 1) {
            std::vector<std::string> names;
            for (const toml::node* m : matches)
              if (const auto* n = m->as_table()->get_as<std::string>("name")) names.push_back(**n);
            fail(line_of(*matches[1], w.line),
                 "'" + key + "': " + std::to_string(matches.size()) + " [[" + path +
                     "]] entries have " + selector + " \"" + part +
                     "\"; give each a distinct name and use it (names: " + quoted_list(names) +
                     ")");
          }
          if (matches.size() == 1) {
            chosen = matches[0];
            how = std::string(selector) + " \"" + part + "\"";
            break;
          }
        }
      }
      if (!chosen) {
        if (auto index = as_index(part); index && *index < array->size()) {
          chosen = array->get(*index);
          how = "number " + part;
        }
      }
      if (!chosen) {
        if (of_tables) {
          std::vector<std::string> names;
          for (const toml::node& entry : *array) {
            const auto* t = entry.as_table();
            const auto* n = t->get_as<std::string>("name");
            if (!n) n = t->get_as<std::string>("group");
            if (n) names.push_back(**n);
          }
          fail(w.line, "'" + key + "': no [[" + path + "]] has name or group \"" + part +
                           "\" (the scene has: " + quoted_list(names) + ")");
        }
        if (array->empty()) fail(w.line, "'" + key + "': '" + path + "' is an empty array");
        fail(w.line, "'" + key + "': '" + path + "' is an array of " +
                         std::to_string(array->size()) + " values; '" + part +
                         "' is not an index from 0 to " + std::to_string(array->size() - 1));
      }
      node = chosen;
      picked_entry = of_tables;
      if (of_tables) {
        w.where = "[[" + path + "]] " + how;
        w.line = line_of(*chosen, w.line);
      }
    } else {
      fail(w.line, "'" + key + "': '" + path + "' is a single value, not a table");
    }
    path += (path.empty() ? "" : ".") + part;
    if (node->is_table() && !picked_entry) {
      w.where = "[" + path + "]";
      w.line = line_of(*node, w.line);
    }
  }
  if (!is_scalar(*node)) {
    if (const toml::table* t = node->as_table())
      fail(line_of(*node, w.line), "'" + key +
                                       "' is a table, not a value; sweep one of its keys (" +
                                       quoted_list(keys_of(*t)) + ")");
    fail(line_of(*node, w.line),
         "'" + key + "' is an array; sweep one of its elements, e.g. '" + key + ".0'");
  }
  w.value = node;
  return w;
}

// Byte offset in `text` of a toml++ source position (1-based line, column in code points).
size_t offset_of(const std::string& text, const toml::source_position& pos) {
  size_t at = 0;
  for (size_t line = 1; line < pos.line; ++line) {
    at = text.find('\n', at);
    if (at == std::string::npos) return text.size();
    ++at;
  }
  for (size_t column = 1; column < pos.column && at < text.size(); ++column) {
    ++at;
    while (at < text.size() && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) ++at;
  }
  return at;
}

// Offset of the start of the line after `line` (1-based).
size_t after_line(const std::string& text, size_t line) {
  size_t at = 0;
  for (size_t l = 0; l < line; ++l) {
    at = text.find('\n', at);
    if (at == std::string::npos) return text.size();
    ++at;
  }
  return at;
}

std::string basic_string(const std::string& s) {
  std::string q = "\"";
  for (char c : s) {
    switch (c) {
      case '"':
        q += "\\\"";
        break;
      case '\\':
        q += "\\\\";
        break;
      case '\n':
        q += "\\n";
        break;
      case '\t':
        q += "\\t";
        break;
      case '\r':
        q += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char esc[8];
          std::snprintf(esc, sizeof esc, "\\u%04x", c);
          q += esc;
        } else {
          q += c;
        }
    }
  }
  return q + "\"";
}

// `text` parsed as one TOML value; nullopt when it is not one.
std::optional<toml::table> parse_value(const std::string& text) {
  try {
    toml::table t = toml::parse("v = " + text + "\n");
    if (t.get("v") && is_scalar(*t.get("v"))) return t;
  } catch (const toml::parse_error&) {
  }
  return std::nullopt;
}

// A number in any spelling strtod takes (".5", "5.", "1e7"); nullopt otherwise.
std::optional<double> loose_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  if (auto t = parse_value(text)) {
    if (auto v = t->get("v")->value<double>()) return *v;
    return std::nullopt;
  }
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size()) return std::nullopt;
  return v;
}

std::string shortest(double v) {
  char buffer[64];
  auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  return std::string(buffer, result.ptr);
}

bool is_boolean_text(const std::string& s) {
  return s == "true" || s == "false";
}

bool is_integer_text(const std::string& s) {
  auto t = parse_value(s);
  return t && t->get("v")->is_integer();
}

bool is_file_key(const std::string& key) {
  return key == "mesh.geometry" || key == "post.reference" || key == "post.gauge_reference";
}

std::string absolute_file(const fs::path& scene, const std::string& file) {
  if (file.empty() || fs::path(file).is_absolute()) return file;
  return fs::absolute(scene.parent_path() / file).lexically_normal().string();
}

struct Edit {
  size_t begin, end;
  std::string replacement;
};

toml::table parse_scene(const std::string& text, const std::string& file) {
  try {
    return toml::parse(text, file);
  } catch (const toml::parse_error& e) {
    throw InputError(file, static_cast<int>(e.source().begin.line),
                     "TOML syntax error: " + std::string(e.description()));
  }
}

}  // namespace

std::string describe(ValueType type) {
  switch (type) {
    case ValueType::kInteger:
      return "an integer";
    case ValueType::kNumber:
      return "a number";
    case ValueType::kString:
      return "a string";
    case ValueType::kBoolean:
      return "a boolean";
  }
  return "a value";
}

SceneText::SceneText(const fs::path& scene) : file_(scene) {
  std::ifstream in(scene, std::ios::binary);
  if (!in)
    throw InputError(scene.string(), 0, "cannot open file (does it exist and is it readable?)");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  text_ = buffer.str();
  table_ = parse_scene(text_, file_.string());
}

std::string key_label(const std::string& key) {
  const std::vector<std::string> parts = split_key(key);
  if (parts.empty()) return key;
  return as_index(parts.back()) && parts.size() > 1 ? parts[parts.size() - 2] + "." + parts.back()
                                                    : parts.back();
}

KeyTarget SceneText::locate(const std::string& key) const {
  const std::string file = file_.string();
  const Walk w = walk(table_, key, [&](int line, const std::string& message) {
    throw InputError(file, line, message);
  });
  KeyTarget target;
  target.key = key;
  target.where = w.where;
  target.leaf = split_key(key).back();
  target.label = key_label(key);
  target.is_file = is_file_key(key);
  target.line = w.line;
  if (w.value) {
    target.present = true;
    target.type = type_of(*w.value);
    const toml::source_region& s = w.value->source();
    target.current = text_.substr(offset_of(text_, s.begin),
                                  offset_of(text_, s.end) - offset_of(text_, s.begin));
    target.line = line_of(*w.value, w.line);
  } else {
    target.new_table = w.create_table;
    target.siblings = keys_of(*w.parent);
  }
  return target;
}

std::vector<std::string> SceneText::literals(const KeyTarget& target,
                                             const std::vector<std::string>& values) const {
  ValueType type = target.type;
  if (!target.present) {
    auto all = [&](auto predicate) { return std::all_of(values.begin(), values.end(), predicate); };
    if (all([](const std::string& v) { return is_boolean_text(trim(v)); }))
      type = ValueType::kBoolean;
    else if (all([](const std::string& v) { return is_integer_text(trim(v)); }))
      type = ValueType::kInteger;
    else if (all([](const std::string& v) { return loose_number(trim(v)).has_value(); }))
      type = ValueType::kNumber;
    else
      type = ValueType::kString;
  }
  const std::string in_scene =
      target.present ? " (the scene has " + target.leaf + " = " + target.current + ")" : "";
  auto wrong = [&](const std::string& value) {
    throw InputError(file_.string(), target.line,
                     "'" + target.key + "' is " + describe(type) + in_scene +
                         "; the sweep value '" + value + "' is not " + describe(type));
  };
  std::vector<std::string> out;
  for (const std::string& raw : values) {
    const std::string v = trim(raw);
    switch (type) {
      case ValueType::kBoolean:
        if (!is_boolean_text(v)) wrong(v);
        out.push_back(v);
        break;
      case ValueType::kInteger: {
        if (auto t = parse_value(v); t && t->get("v")->is_integer()) {
          out.push_back(std::to_string(t->get("v")->value<int64_t>().value()));
          break;
        }
        const std::optional<double> d = loose_number(v);
        if (!d || !std::isfinite(*d) || *d != std::floor(*d) || std::abs(*d) > 9.0e15) wrong(v);
        out.push_back(std::to_string(static_cast<long long>(*d)));
        break;
      }
      case ValueType::kNumber: {
        auto t = parse_value(v);
        if (t && t->get("v")->is_floating_point()) {
          out.push_back(v);
        } else if (t && t->get("v")->is_integer()) {
          out.push_back(std::to_string(t->get("v")->value<int64_t>().value()) + ".0");
        } else {
          const std::optional<double> d = loose_number(v);
          if (!d || !std::isfinite(*d)) wrong(v);
          std::string s = shortest(*d);
          if (s.find_first_of(".e") == std::string::npos) s += ".0";
          out.push_back(s);
        }
        break;
      }
      case ValueType::kString: {
        std::string s = v;
        // A value written with TOML quotes is taken without them.
        if (auto t = parse_value(v); t && t->get("v")->is_string())
          s = **t->get_as<std::string>("v");
        if (target.is_file) s = absolute_file(file_, s);
        out.push_back(basic_string(s));
        break;
      }
    }
  }
  return out;
}

std::string SceneText::with_value(const KeyTarget& target, const std::string& literal,
                                  const std::vector<std::string>& note) const {
  return with_values({{target, literal}}, note);
}

std::string SceneText::with_values(const std::vector<KeySetting>& settings,
                                   const std::vector<std::string>& note) const {
  std::vector<Edit> edits;
  auto swept = [&](const std::string& key) {
    return std::any_of(settings.begin(), settings.end(),
                       [&](const KeySetting& s) { return s.target.key == key; });
  };
  // The file references, made absolute (unless a swept key is one of them).
  for (const char* file_key : {"mesh.geometry", "post.reference", "post.gauge_reference"}) {
    if (swept(file_key)) continue;
    const std::vector<std::string> parts = split_key(file_key);
    const auto* table = table_.get_as<toml::table>(parts[0]);
    const auto* value = table ? table->get_as<std::string>(parts[1]) : nullptr;
    if (!value) continue;
    const std::string absolute = absolute_file(file_, value->get());
    if (absolute == value->get()) continue;
    edits.push_back({offset_of(text_, value->source().begin), offset_of(text_, value->source().end),
                     basic_string(absolute)});
  }
  const std::string file = file_.string();
  // Keys of tables the scene does not have, per table in the order given: each new table is
  // written once (a second [solver] header would not parse).
  std::vector<std::pair<std::string, std::string>> new_tables;
  for (const auto& [target, literal] : settings) {
    auto fail = [&](int line, const std::string& message) -> void {
      throw InputError(file, line, message);
    };
    const Walk w = walk(table_, target.key, fail);
    if (w.value) {
      edits.push_back({offset_of(text_, w.value->source().begin),
                       offset_of(text_, w.value->source().end), literal});
    } else if (w.create_table) {
      const std::vector<std::string> parts = split_key(target.key);
      auto table = std::find_if(new_tables.begin(), new_tables.end(),
                                [&](const auto& t) { return t.first == parts[0]; });
      if (table == new_tables.end())
        table = new_tables.insert(new_tables.end(), {parts[0], "\n[" + parts[0] + "]\n"});
      table->second += parts[1] + " = " + literal + "\n";
    } else if (w.parent == &table_) {
      edits.push_back({0, 0, target.leaf + " = " + literal + "\n"});
    } else {
      if (w.parent->is_inline())
        fail(target.line, "'" + target.key + "': the scene does not set '" + target.leaf +
                              "' and it cannot be added to an inline table; write it in the scene");
      const size_t at = after_line(text_, w.parent->source().begin.line);
      std::string line = target.leaf + " = " + literal + "\n";
      if (at == text_.size() && !text_.empty() && text_.back() != '\n') line = "\n" + line;
      edits.push_back({at, at, line});
    }
  }
  // New tables at the end of the file, where a table header is always allowed.
  if (!new_tables.empty()) {
    std::string block = (text_.empty() || text_.back() == '\n') ? "" : "\n";
    for (const auto& table : new_tables) block += table.second;
    edits.push_back({text_.size(), text_.size(), block});
  }
  // From the end, so that earlier offsets stay valid. Of two lines inserted at the same place
  // the later one goes in first, so that the copy lists them in the order given.
  std::reverse(edits.begin(), edits.end());
  std::stable_sort(edits.begin(), edits.end(),
                   [](const Edit& a, const Edit& b) { return a.begin > b.begin; });
  std::string copy = text_;
  for (const Edit& e : edits) copy.replace(e.begin, e.end - e.begin, e.replacement);
  if (!note.empty()) {
    if (!copy.empty() && copy.back() != '\n') copy += "\n";
    copy += "\n";
    for (const std::string& line : note) copy += "# " + line + "\n";
  }

  // The copy must parse and hold each value where its key says.
  for (const auto& [target, literal] : settings) {
    const std::string placed = value_in(copy, target.key);
    const auto expected = parse_value(literal);
    const auto got = placed.empty() ? std::nullopt : parse_value(placed);
    if (!expected || !got || !(*expected == *got))
      throw InputError(file, target.line,
                       "'" + target.key + "' = " + literal +
                           " could not be written into a copy of the scene (the scene does not "
                           "set it, and where it would go is ambiguous); write '" +
                           target.leaf + "' into the scene and sweep again");
  }
  return copy;
}

std::string SceneText::value_in(const std::string& text, const std::string& key) {
  toml::table table;
  try {
    table = toml::parse(text);
  } catch (const toml::parse_error&) {
    return "";
  }
  try {
    const Walk w = walk(table, key,
                        [](int, const std::string& message) { throw std::runtime_error(message); });
    if (!w.value) return "";
    const size_t b = offset_of(text, w.value->source().begin);
    return text.substr(b, offset_of(text, w.value->source().end) - b);
  } catch (const std::runtime_error&) {
    return "";
  }
}

}  // namespace lituya::sweep
