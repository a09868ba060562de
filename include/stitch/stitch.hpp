// stitch's public API in one include: read or build a mesh, edit it, build a smooth surface
// with a method and K-gon controls, evaluate it exactly, tessellate, analyse and export.
// docs/library.md is the tutorial. The renderer (<stitch/render/...>, stitch::render) and the
// modeler library (<stitch/modeler/...>, stitch::modeler) are separate components.
#pragma once

// errors: stitch::Error and its kinds
#include "stitch/error.hpp"

// mesh: the half-edge mesh, building it from polygons with every check (repairing what it can),
// file I/O
#include "stitch/mesh/build.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"
#include "stitch/mesh/io.hpp"
#include "stitch/mesh/mesh_journal.hpp"
#include "stitch/mesh/polygon.hpp"
#include "stitch/mesh/polygon_soup.hpp"
#include "stitch/mesh/repair.hpp"
#include "stitch/mesh/validate.hpp"

// topology: the operators (insert/delete edge and those built on them), remeshing, primitives
#include "stitch/topology/compare.hpp"
#include "stitch/topology/connect_faces.hpp"
#include "stitch/topology/delete_face.hpp"
#include "stitch/topology/edge_ops.hpp"
#include "stitch/topology/extrude.hpp"
#include "stitch/topology/features.hpp"
#include "stitch/topology/insert_edge.hpp"
#include "stitch/topology/operation.hpp"
#include "stitch/topology/primitives.hpp"
#include "stitch/topology/remesh.hpp"

// K-gons and control nets
#include "stitch/kgon/kgon.hpp"
#include "stitch/kgon/kgon_topology.hpp"
#include "stitch/net/control_net.hpp"

// evaluation: Bézier patches, the (modified) de Casteljau split, the surface of a method
#include "stitch/eval/bezier.hpp"
#include "stitch/eval/bezier_surface.hpp"
#include "stitch/eval/catmull_clark.hpp"
#include "stitch/eval/de_casteljau.hpp"
#include "stitch/eval/surface.hpp"

// tessellation and export
#include "stitch/tess/bezier_json.hpp"
#include "stitch/tess/export.hpp"
#include "stitch/tess/incremental_surface.hpp"
#include "stitch/tess/patch_grid.hpp"
#include "stitch/tess/patches.hpp"
#include "stitch/tess/surface_change.hpp"
#include "stitch/tess/tessellate.hpp"
#include "stitch/tess/tessellated_mesh.hpp"

// analysis: continuity measured, surface checks
#include "stitch/analysis/continuity.hpp"
#include "stitch/analysis/surface_check.hpp"

// project files: a mesh with its K-gon controls (the modeler's .stitch), K-gon controls files
#include "stitch/project/kgon_controls.hpp"
#include "stitch/project/project_file.hpp"
