// Operation lines: the text form of the topology operators, shared by `stitch edit` and the
// modeler. Syntax and numbering are documented in docs/editing.md. Numbers are 1-based as in OBJ
// and refer to the mesh as it stands (deleted elements leave gaps, new ones take the next
// numbers), so a sequence of operations can be written against one numbering.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/mesh/validate.hpp"
#include "stitch/topology/connect_faces.hpp"
#include "stitch/topology/remesh.hpp"
#include "stitch/topology/verdict.hpp"

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
/// A line without its `# comment`. '#' also marks an occurrence in a corner (V@F#k): only a '#'
/// at the start or after a blank starts a comment.
std::string_view without_comment(std::string_view line);

/// The typed operations, one per operator: what `stitch edit`, scripts, the modeler and Python
/// apply. Elements are the mesh's handles; parse_operation resolves a line's 1-based numbers.
namespace ops {
struct InsertEdge {
  Corner a, b;
  bool operator==(const InsertEdge&) const = default;
};
struct DeleteEdge {
  Edge edge;
  bool operator==(const DeleteEdge&) const = default;
};
struct SubdivideEdge {
  Edge edge;
  bool operator==(const SubdivideEdge&) const = default;
};
struct CollapseEdge {
  Edge edge;
  Vertex keep;  ///< the end that stays (at the edge's midpoint)
  bool operator==(const CollapseEdge&) const = default;
};
struct ExtrudeFace {
  Face face;
  double distance = 0, scale = 1;
  bool operator==(const ExtrudeFace&) const = default;
};
struct ConnectFaces {
  Face f, g;
  HandleOptions handle;  ///< twist (none: the least), segments, waist
  bool operator==(const ConnectFaces&) const = default;
};
struct DeleteFace {
  Face face;
  bool operator==(const DeleteFace&) const = default;
};
struct OpenFace {
  Face face;
  bool operator==(const OpenFace&) const = default;
};
struct FillHole {
  Face face;
  bool operator==(const FillHole&) const = default;
};
struct SetCrease {
  Edge edge;
  double sharpness = 0;
  bool operator==(const SetCrease&) const = default;
};
struct SetCorner {
  Vertex vertex;
  double sharpness = 0;
  bool operator==(const SetCorner&) const = default;
};
struct Remesh {
  Remeshing scheme;
  bool operator==(const Remesh&) const = default;
};
}  // namespace ops

using Operation =
    std::variant<ops::InsertEdge, ops::DeleteEdge, ops::SubdivideEdge, ops::CollapseEdge,
                 ops::ExtrudeFace, ops::ConnectFaces, ops::DeleteFace, ops::OpenFace, ops::FillHole,
                 ops::SetCrease, ops::SetCorner, ops::Remesh>;

/// One row of the operation table, which every front end reads (help texts, the modeler's
/// buttons and script language, the undo history).
struct OperationInfo {
  std::string_view name;       ///< the first word of its line, e.g. "insert-edge"
  std::string_view synopsis;   ///< the line with placeholders, e.g. "insert-edge V@F V@F"
  std::string_view arguments;  ///< what it takes, in words, e.g. "two corners"
  std::string_view summary;    ///< what it does, in a few words
  bool renumbers = false;      ///< the result is a new mesh numbered afresh (the remeshings)
};

/// Every operation, in the order help texts list them.
std::span<const OperationInfo> operation_table();

/// The table's row named `name`, or nullptr.
const OperationInfo* find_operation(std::string_view name);

/// The table's row of `op`.
const OperationInfo& operation_info(const Operation& op);

/// The table's names, comma-separated, for messages that list them.
std::string operation_names();

/// Parses one operation line ("insert-edge 1@1 5@2", "extrude-face 3 0.5", ...) against the mesh
/// as it stands. Leading/trailing blanks and a trailing `# comment` are ignored; a blank or
/// comment-only line gives nothing. Throws UsageError for an unknown operation or bad arguments
/// (a number that names no element of the mesh included), saying what and where.
std::optional<Operation> parse_operation(const HalfedgeMesh& mesh, std::string_view line);

/// The line parse_operation reads back as `op` on this mesh (so: before `op` is applied).
std::string format_operation(const HalfedgeMesh& mesh, const Operation& op);

/// Whether `op` applies to the mesh, without changing it: the operator's own can_* check, in the
/// operator's words. Cheap for the local operators (constant or in proportion to the elements'
/// degrees; open-face merging with a hole and delete-face work on a copy, as the operators do;
/// the remeshings read the whole mesh). apply_operation with the full census also makes sure
/// the result reads back from a file, which no check before the edit can promise.
Verdict can_apply(const HalfedgeMesh& mesh, const Operation& op);

/// Applies `op`. Throws (the mesh is unchanged) when it is refused, saying why; the message
/// starts with the operation's name.
OperationReport apply_operation(HalfedgeMesh& mesh, const Operation& op,
                                Census census = Census::full);

/// Parses and applies one operation line; a blank or comment-only line does nothing and returns
/// an empty `what`.
OperationReport apply_operation(HalfedgeMesh& mesh, std::string_view line,
                                Census census = Census::full);

/// Resolves `V@F` or `V@F#k` to the corner (the half-edge of face F leaving vertex V).
Corner parse_corner(const HalfedgeMesh& mesh, std::string_view text);

/// Corner c as parse_corner reads it: `V@F`, or `V@F#k` when vertex V appears on face F more
/// than once (k counts its appearances along the face from the face's first corner). The one name
/// of a corner, and so of its patch, everywhere: operations, `stitch eval`, Bézier JSON, the
/// faces of STEP and IGES files, Python.
std::string corner_name(const HalfedgeMesh& mesh, Corner c);
/// The k of corner c's name `V@F#k`; 0 when its vertex appears on its face once (no `#k`).
int corner_occurrence(const HalfedgeMesh& mesh, Corner c);
/// The name of the corner of `vertex` on `face` (0-based indices) with that occurrence (0: the
/// vertex appears on the face once), for data that keeps the three numbers without the mesh.
std::string corner_name(int vertex, int face, int occurrence);

/// Resolves an edge given as its two end vertices `V W`, or `V W@F` to pick the one on face F's
/// loop when several edges join V and W, or `V W@F#k` for the k-th time F's loop runs from V to
/// W. The returned edge's ends are V and W in either order.
Edge parse_edge(const HalfedgeMesh& mesh, std::string_view v_text, std::string_view w_text);

/// Edge e as parse_edge reads it (two words): `V W`, or `V W@F` / `V W@F#k` when several edges
/// join V and W; the end `first`, when given, is written first.
std::string edge_name(const HalfedgeMesh& mesh, Edge e, Vertex first = {});

}  // namespace stitch
