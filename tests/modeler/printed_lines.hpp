// What a session's script lines print, collected for the tests that read it.
#pragma once

#include <string>
#include <vector>

#include "stitch/modeler/session.hpp"

namespace stitch::modeler {

struct Printed {
  std::vector<std::string> lines;
  ScriptHooks hooks() {
    ScriptHooks h;
    h.print = [this](const std::string& t) { lines.push_back(t); };
    return h;
  }
};

}  // namespace stitch::modeler
