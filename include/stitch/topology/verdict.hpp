// The answer of an operator's can_* check (in the style of pmp-library's is_collapse_ok beside
// collapse): whether the operation applies to the mesh as it stands, and if not, why. A front end
// enables its buttons from it without trying the edit; the operator itself refuses with the same
// words.
#pragma once

#include <string>
#include <utility>

#include "stitch/error.hpp"

namespace stitch {

class Verdict {
 public:
  Verdict() = default;  ///< applies
  static Verdict refused(std::string why) {
    Verdict v;
    v.refusal_ = std::move(why);
    return v;
  }
  [[nodiscard]] bool applies() const { return refusal_.empty(); }
  explicit operator bool() const { return applies(); }
  /// Why it does not apply (empty when it does).
  [[nodiscard]] const std::string& refusal() const { return refusal_; }
  /// For the operators: throws TopologyError with the refusal when there is one.
  void throw_if_refused() const {
    if (!applies()) throw TopologyError(refusal_);
  }

 private:
  std::string refusal_;
};

}  // namespace stitch
