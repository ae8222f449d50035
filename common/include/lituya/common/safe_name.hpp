#pragma once
// Names the user gives that Lituya turns into file names (a stage "release" writes
// release_points.pvd) or uses as identifiers in other files (material names). A name that
// holds a '/', a quote, '&' or a line break once passed `lituya pre` and broke a later write
// or the XML of a .pvd, so every such name is checked where it is read, against one safe
// alphabet that is valid in a file name on every system and needs no escaping in XML, CSV or
// TOML:
//   letters A-Z and a-z, digits 0-9, '_', '-' and '.';
//   1 to kMaxSafeNameLength characters;
//   not starting with '.' (hidden files, "." and "..") or '-' (read as an option by tools);
//   no "..".
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace lituya {

inline constexpr std::size_t kMaxSafeNameLength = 64;

// The rule above in one phrase, for error messages.
std::string_view safe_name_rule();

// Why `name` breaks the rule (e.g. "it contains '/'"), or nothing when it is safe.
std::optional<std::string> safe_name_problem(std::string_view name);

// `text` in double quotes with line breaks, tabs and other control or non-ASCII bytes shown
// as escapes (\n, \t, \xNN), so a message that quotes a bad name stays on one line.
std::string quoted_for_message(std::string_view text);

}  // namespace lituya
