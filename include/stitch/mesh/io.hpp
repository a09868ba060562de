// Reading and writing polygon meshes: OBJ, OFF, PLY (ASCII and binary) in; OBJ, OFF, PLY, STL out.
#pragma once

#include <functional>
#include <iosfwd>
#include <string>
#include <vector>

#include "stitch/mesh/build.hpp"
#include "stitch/mesh/halfedge_mesh.hpp"

namespace stitch {

/// Reads a polygon soup; the format is chosen by the file's extension (.obj, .off, .ply, .stl).
/// STL (ASCII or binary) has no shared vertices: corners closer than 1e-6 of the bounding box
/// diagonal are welded into one vertex, and triangles that collapse in the welding are dropped.
/// OBJ: faces of any degree, negative (relative) indices accepted, normal indices ignored,
/// OpenSubdiv's `t` crease and corner tags read, other tags and unsupported statements ignored
/// (one warning each kind).
/// Texture coordinates (PolygonSoup::uvs, face_uvs): OBJ `vt` with `f v/vt` (every face or
/// none), PLY per-vertex `s t` (or `texture_u texture_v`, `texture_s texture_t`, `u v`), glTF
/// TEXCOORD_0 (v flipped to OBJ's convention: 0 at the bottom).
/// Throws stitch::Error naming the file and line (or element) for anything malformed.
/// PolygonSoup::numbering says how the format numbers its elements, for later messages.
/// `progress`, if set, is told how much of the work is done (0 to 1) from time to time: the
/// bytes read, then the lines parsed (OBJ, the format of the largest meshes).
PolygonSoup read_polygon_soup(const std::string& path, std::vector<std::string>* warnings = nullptr,
                              const std::function<void(double)>& progress = {});

/// read_polygon_soup + build_mesh, which repairs what it can unless options.repair is off
/// (report->repair says what, and its summary opens report->warnings); report->corner_uvs gets
/// the file's texture coordinates.
/// `progress` as for read_polygon_soup, building the mesh counted as the last tenth.
HalfedgeMesh read_mesh(const std::string& path, const BuildOptions& options = {},
                       BuildReport* report = nullptr, std::vector<std::string>* warnings = nullptr,
                       const std::function<void(double)>& progress = {});

/// Writes the soup; format by extension (.obj, .off, .ply as ASCII, .stl as binary triangles
/// with each polygon fanned). Atomic: written to a temporary file beside `path`, then renamed.
void write_polygon_soup(const std::string& path, const PolygonSoup& soup);
void write_mesh(const std::string& path, const HalfedgeMesh& mesh);

/// Runs `write` on a stream to a temporary file in the same folder as `path` and renames it
/// into place when `write` returns; on any error the temporary file is removed, `path` is left
/// as it was, and the error is rethrown (as stitch::Error for I/O failures).
void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary = false);
/// Throws OutputError where a file cannot be written at `path` at all: its folder does not
/// exist, or it is a folder. The atomic writers check it first; front ends check it before a
/// long computation, so that it fails at once.
void check_output_path(const std::string& path);
/// The same for writers that can only write to a path (OpenCASCADE's): `write` gets the
/// temporary file's path. A target that exists and is not a regular file (a device such as
/// /dev/stdout or /dev/full, a pipe) is not replaced: the bytes are written to it, and a write
/// error (ENOSPC) is thrown like any other.
void write_file_atomically_at(const std::string& path,
                              const std::function<void(const std::string& temporary)>& write);

/// The bytes of a regular file (after following symbolic links). Pipes, devices and sockets
/// are refused, since reading them may never end. Throws stitch::Error naming the file. `progress`
/// (optional) gets the fraction of the bytes read.
std::string read_regular_file(const std::string& path,
                              const std::function<void(double)>& progress = {});

/// Lower-case extension of a path including the dot (".obj"), or "" when it has none.
std::string file_extension(const std::string& path);

}  // namespace stitch
