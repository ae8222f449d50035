#pragma once
// Escaping of text written into XML attribute values (the .vtu and .pvd files). Every
// attribute value Lituya writes goes through xml_escaped, so a name holding '&', '<' or a
// quote still gives a well-formed file (a .pvd once broke on a stage named a&b).
#include <string>
#include <string_view>

namespace lituya {

// `text` for use inside a double- or single-quoted XML attribute value: & < > " ' become
// entities; tab, line feed and carriage return become character references (an XML parser
// turns literal ones into spaces); other control characters, which XML 1.0 cannot hold at
// all, become '?'.
std::string xml_escaped(std::string_view text);

}  // namespace lituya
