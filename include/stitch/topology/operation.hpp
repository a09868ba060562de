// Operation lines: the text form of the topology operators, shared by `stitch edit` and the
// modeler. Syntax and numbering are documented in docs/editing.md. Numbers are 1-based as in OBJ
// and refer to the mesh as it stands (deleted elements leave gaps, new ones take the next
// numbers), so a sequence of operations can be written against one numbering.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/mesh/validate.hpp"

namespace stitch {

struct OperationReport {
  std::string what;     ///< what changed, e.g. "split face 3 into faces 3 and 7 by new edge 13"
  TopologyStats stats;  ///< counts after the operation (see apply_operation's `census`)
  bool components_counted = true;  ///< stats has genus and components (and the histograms)
  /// One line: the operation, what changed, then V E F, Euler characteristic, and genus and
  /// components when counted, followed by the boundary loops, creases and corners when there
  /// are any.
  [[nodiscard]] std::string summary(std::string_view op_text) const;
};

/// How much of the topology apply_operation recounts for its report: everything (a pass over
/// the whole mesh), or only what is known without one (V, E, F, Euler characteristic; F and the
/// Euler characteristic then count hole faces too, telling them apart takes the pass), for
/// callers that must not pay in proportion to the mesh, such as the modeler. With the full
/// census the result must also pass check_reads_back (the operation is refused, and the mesh
/// left as it was, when it does not); without it the reader's exhaustive pairing search is
/// what makes the result read back (see build_mesh).
enum class Census { full, counts_only };

/// The words of a line, split at white space.
std::vector<std::string_view> split_words(std::string_view line);

/// Parses and applies one operation line ("insert-edge 1@1 5@2", "extrude-face 3 0.5", ...).
/// Leading/trailing blanks and a trailing `# comment` are ignored. Throws MeshError (the mesh is
/// unchanged) for an unknown operation, bad arguments, or a refused operation, saying why.
/// A blank or comment-only line does nothing and returns an empty `what`.
OperationReport apply_operation(HalfedgeMesh& mesh, std::string_view line,
                                Census census = Census::full);

/// The operations with their arguments, one per entry, for help texts.
std::vector<std::string> operation_synopsis();

/// Resolves `V@F` or `V@F#k` to the corner (the half-edge of face F leaving vertex V).
Corner parse_corner(const HalfedgeMesh& mesh, std::string_view text);

/// Resolves an edge given as its two end vertices `V W`, or `V W@F` to pick the one on face F's
/// loop when several edges join V and W. The returned edge's ends are V and W in either order.
Edge parse_edge(const HalfedgeMesh& mesh, std::string_view v_text, std::string_view w_text);

}  // namespace stitch
