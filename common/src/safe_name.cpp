#include "lituya/common/safe_name.hpp"

#include <cstdio>

namespace lituya {

namespace {
// ASCII only and independent of the locale: std::isalnum would accept other letters under
// some locales, and those are not portable in file names.
bool is_safe_character(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.';
}

std::string hex_byte(char c) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02X", static_cast<unsigned>(static_cast<unsigned char>(c)));
  return text;
}

// How a refused character is named in a message: "'/'", "a space", "a line break", ...
std::string describe(char c) {
  switch (c) {
    case ' ':
      return "a space";
    case '\n':
    case '\r':
      return "a line break";
    case '\t':
      return "a tab";
    default:
      break;
  }
  const auto byte = static_cast<unsigned char>(c);
  if (byte < 0x20 || byte == 0x7F) return "the control character " + hex_byte(c);
  if (byte >= 0x80) return "a non-ASCII character (byte " + hex_byte(c) + ")";
  return std::string("'") + c + "'";
}
}  // namespace

std::string_view safe_name_rule() {
  return "a name may hold only ASCII letters, digits, '_', '-' and '.', must be 1 to 64 "
         "characters long, must not start with '.' or '-' and must not contain \"..\"";
}

std::optional<std::string> safe_name_problem(std::string_view name) {
  static_assert(kMaxSafeNameLength == 64, "update safe_name_rule() and the manuals");
  if (name.empty()) return "it is empty";
  for (char c : name)
    if (!is_safe_character(c)) return "it contains " + describe(c);
  if (name.size() > kMaxSafeNameLength)
    return "it has " + std::to_string(name.size()) + " characters";
  if (name.front() == '.') return "it starts with '.'";
  if (name.front() == '-') return "it starts with '-'";
  if (name.find("..") != std::string_view::npos) return "it contains \"..\"";
  return std::nullopt;
}

std::string quoted_for_message(std::string_view text) {
  std::string out = "\"";
  for (char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    if (c == '\n')
      out += "\\n";
    else if (c == '\r')
      out += "\\r";
    else if (c == '\t')
      out += "\\t";
    else if (c == '"' || c == '\\')
      out += std::string("\\") + c;
    else if (byte < 0x20 || byte >= 0x7F)
      out += "\\x" + hex_byte(c).substr(2);
    else
      out += c;
  }
  return out + "\"";
}

}  // namespace lituya
