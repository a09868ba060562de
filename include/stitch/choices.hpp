// Named values: one table per concept (methods, K-gon constructions, boundary rules, UV modes,
// face packings, render modes), each row a name, its value and a line of help. The command
// line's options and help, Python's keyword arguments and the modeler's menus all read the
// tables, so a name is written once.
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "stitch/error.hpp"

namespace stitch {

template <class T>
struct Choice {
  std::string_view name;
  T value;
  std::string_view help;
};

template <class T>
using ChoiceTable = std::span<const Choice<T>>;

/// "a, b, c" (or with another separator).
template <class T>
std::string choice_names(ChoiceTable<T> table, std::string_view separator = ", ") {
  std::string out;
  for (const Choice<T>& c : table) {
    if (!out.empty()) out += separator;
    out += c.name;
  }
  return out;
}

/// "a: help a; b: help b", for help texts.
template <class T>
std::string choice_help(ChoiceTable<T> table) {
  std::string out;
  for (const Choice<T>& c : table) {
    if (!out.empty()) out += "; ";
    out += std::string(c.name) + ": " + std::string(c.help);
  }
  return out;
}

/// The row of `value` (the table's first row if no row has it, which a complete table rules out).
template <class T>
const Choice<T>& choice_of(ChoiceTable<T> table, T value) {
  for (const Choice<T>& c : table)
    if (c.value == value) return c;
  return table.front();
}

template <class T>
std::string_view choice_name(ChoiceTable<T> table, T value) {
  return choice_of(table, value).name;
}

/// The value named `text`; throws UsageError "unknown <what> 'text' (known: ...)" otherwise.
template <class T>
T parse_choice(ChoiceTable<T> table, std::string_view text, std::string_view what) {
  for (const Choice<T>& c : table)
    if (c.name == text) return c.value;
  throw UsageError("unknown " + std::string(what) + " '" + std::string(text) +
                   "' (known: " + choice_names(table) + ")");
}

}  // namespace stitch
