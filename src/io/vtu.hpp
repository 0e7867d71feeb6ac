// VTK XML UnstructuredGrid files (.vtu; "VTK File Formats", VTK User's Guide), read and
// written.
//
// Reading: ASCII, inline binary (base64 of a UInt32 or UInt64 byte-count header followed by
// the data) and appended data (base64 or raw), little-endian; points Float32/Float64, cell
// arrays of any integer type; several pieces are concatenated. Cell types 10 (VTK_TETRA)
// and 24 (VTK_QUADRATIC_TETRA, corners first) become tets, 5 (VTK_TRIANGLE) and 22
// (VTK_QUADRATIC_TRIANGLE) faces; other types are counted in ReadInfo::skipped_elements,
// and a file without tets but with other cells is rejected. Point arrays "pdr_point_marker"
// and cell arrays "pdr_region" and "pdr_face_marker" (written by pdr) fill the markers.
// zlib-compressed data (compressor="vtkZLibDataCompressor", ParaView's default) is read
// when pdr_io was built with zlib; other compressors (LZ4, LZMA), or zlib without it, are
// rejected with advice to re-export uncompressed.
//
// Orientation: VTK_TETRA's documented convention is that points 0,1,2, by the right-hand
// rule, have a normal pointing toward point 3, i.e. det[b-a, c-a, d-a] > 0; Gmsh 4.8.4's VTK
// export of a box (1125/1125 tets positive) agrees. That is pdr's convention: tets are read
// and written unchanged. VTK has no face convention; triangles are kept as they are.
//
// Writing: version 1.0, UInt64 headers; points Float64; connectivity and offsets Int32 when
// they fit, else Int64; types UInt8. Cells are the tets (type 10) followed by the faces
// (type 5). Per-cell fields are given per tet; their value on face cells is NaN. Per-point
// fields are given per point. The default encoding is raw appended data (smallest, fastest;
// ParaView's own default); ASCII, inline base64 and appended base64 are available.
#pragma once

#include <string>
#include <vector>

#include "io/read_info.hpp"
#include "mesh/mesh_data.hpp"

namespace pdr::io {

struct CellField {
  std::string name;
  std::vector<double> values;  // one per tet
};

struct PointField {
  std::string name;
  std::vector<double> values;  // one per point
};

enum class VtuEncoding { Ascii, InlineBase64, AppendedBase64, AppendedRaw };

struct VtuOptions {
  VtuEncoding encoding = VtuEncoding::AppendedRaw;
  bool write_faces = true;  // also write MeshData::faces as triangle cells
};

MeshData read_vtu(const std::string& path, ReadInfo* info = nullptr);

// Throws std::invalid_argument (before creating any file) when a field's size does not
// match the mesh.
void write_vtu(const MeshData& mesh, const std::string& path,
               const std::vector<CellField>& cell_fields = {},
               const std::vector<PointField>& point_fields = {}, const VtuOptions& options = {});

}  // namespace pdr::io
