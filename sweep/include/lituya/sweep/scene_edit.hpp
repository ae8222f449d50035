#pragma once
// One value of a scene, changed in a copy of the scene file. A sweep key is a dotted path to
// one scalar of scene.toml: `mesh.cell_size`, `material.beads.friction_angle`,
// `stage.release.courant`, `boundary.bed.friction`, `gravity.1`. The entries of an array of
// tables ([[material]], [[stage]], [[region]], [[boundary]]) are picked by their `name`, else
// by their `group`, else by their index from 0; the elements of an array of values by index.
//
// The copy is the user's text with only that value replaced (comments, layout and line
// numbers kept), so that a run's scene.toml reads like the original and an error at line N of
// the copy is at line N of the original too. The file references of the scene (mesh.geometry,
// post.reference, post.gauge_reference) are made absolute, so the copy runs from any folder.
#include <filesystem>
#include <string>
#include <vector>

#include <toml++/toml.h>

namespace lituya::sweep {

enum class ValueType { kInteger, kNumber, kString, kBoolean };
// "an integer", "a number", "a string", "a boolean" (for messages).
std::string describe(ValueType type);

// The short name of a key for tables: its last part ("friction_angle" for
// `material.beads.friction_angle`), with the part before it for an index ("gravity.1").
std::string key_label(const std::string& key);

// Where a sweep key points in the scene.
struct KeyTarget {
  std::string key;                      // as given
  std::string where;                    // for messages, e.g. "[[material]] \"beads\""
  std::string leaf;                     // the last key, e.g. "friction_angle"
  std::string label;                    // key_label(key)
  std::vector<std::string> siblings;    // the keys the scene sets next to it, or at the top
                                        // level for a new table (when not present)
  bool present = false;                 // false: the scene does not set it, a copy adds it
  bool new_table = false;               // not present, nor its top-level table: a copy adds both
  ValueType type = ValueType::kNumber;  // of the scene's value (meaningful when present)
  std::string current;                  // the scene's value as written (when present)
  int line = 0;                         // scene line of the value, or of the table that gets it
  bool is_file = false;                 // a file reference, resolved against the scene's folder
};

// One key of a scene copy and the TOML text of its value (one of SceneText::literals()).
struct KeySetting {
  KeyTarget target;
  std::string literal;
};

class SceneText {
 public:
  // Reads and parses the scene; InputError naming the file (and line) when it cannot be read
  // or is not valid TOML.
  explicit SceneText(const std::filesystem::path& scene);

  const std::filesystem::path& file() const { return file_; }
  const std::string& text() const { return text_; }
  const toml::table& table() const { return table_; }

  // Resolves `key`. A missing last key is allowed (the copies add it; the scene reader then
  // judges it), and so is a missing top-level table when the key has two parts
  // (`solver.flip_fraction` in a scene without [solver]). Anything else that does not exist,
  // an ambiguous entry, or a key that names a table or an array instead of one value, is an
  // InputError naming the scene file, the line and what the scene has there.
  KeyTarget locate(const std::string& key) const;

  // The TOML text of each value for `target`, in order: "18" becomes "18.0" for a number key,
  // strings are quoted (file references made absolute against the scene's folder). A value
  // that does not fit the scene's type is an InputError at the key's line. For a key the
  // scene does not set, the type is that of all values: boolean, integer, number or string.
  std::vector<std::string> literals(const KeyTarget& target,
                                    const std::vector<std::string>& values) const;

  // The scene text with `target` set to `literal` (one of literals()), the file references
  // made absolute, and `note` (lines without '#') appended as comments at the end. Checked by
  // parsing the result; InputError when the value cannot be placed (for example a key to add
  // to an inline table).
  std::string with_value(const KeyTarget& target, const std::string& literal,
                         const std::vector<std::string>& note) const;

  // The same with several keys set at once (a sweep over several parameters). The keys must
  // be distinct; keys added to a table the scene does not have go under one new header.
  std::string with_values(const std::vector<KeySetting>& settings,
                          const std::vector<std::string>& note) const;

  // The value `key` has in `text` (a copy), as TOML text; empty when it is not set. Used to
  // check the copies, and by tests.
  static std::string value_in(const std::string& text, const std::string& key);

 private:
  std::filesystem::path file_;
  std::string text_;
  toml::table table_;
};

}  // namespace lituya::sweep
