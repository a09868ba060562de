// Reading the documentation pages, for the tests that check a page describes what a table holds.
#pragma once

#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

namespace stitch::modeler {

/// The text of docs/NAME, empty when it is not there.
inline std::string read_docs(const std::string& name) {
  std::ifstream in(std::string(STITCH_SOURCE_DIR) + "/docs/" + name);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Whether `text` shows `name` as a line's first word in code: `name` followed by a blank or
/// the closing backtick (a bare word such as "view" or "open" is on any page).
inline bool names_in_code(const std::string& text, std::string_view name) {
  // Appended rather than "`" + name, where GCC 12 warns wrongly (-Wrestrict).
  std::string start(1, '`');
  start += name;
  return text.find(start + " ") != std::string::npos || text.find(start + "`") != std::string::npos;
}

}  // namespace stitch::modeler
