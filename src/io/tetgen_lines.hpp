// The lines of TetGen's mesh files (io/tetgen.hpp: the columns, 1-based numbers, faces
// written as (a, c, b)), for the writer of whole files and for writers that format one
// file in parts, each part its own run of entities (par/rank_files.hpp: every rank lists
// its tets). A file is its header, the lines of its entities in order, and the tail; the
// lines of entities [first, first + n) number them first + 1 .. first + n, so parts made
// apart and joined in order are the file the whole writer makes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "io/text_sink.hpp"
#include "mesh/mesh_data.hpp"

namespace pdr::io::tetgen_lines {

void node_header(TextSink& out, std::size_t points, bool markers);
// `markers`: empty, or one per point.
void nodes(TextSink& out, std::span<const Point> points, std::size_t first,
           std::span<const int> markers);

void ele_header(TextSink& out, std::size_t tets, bool regions);
// `regions`: empty, or one per tet.
void eles(TextSink& out, std::span<const Tet> tets, std::size_t first, std::span<const int> regions);

void face_header(TextSink& out, std::size_t faces, bool markers);
// `markers`: empty, or one per face.
void faces(TextSink& out, std::span<const Tri> faces, std::size_t first,
           std::span<const int> markers);

// The last line of every file.
void tail(TextSink& out);

// The exact length in bytes of what eles() writes for the same arguments, from the
// numbers' digits (a part of a file written at its offset as it is formatted:
// par/rank_files.hpp, StreamedPart).
std::uint64_t eles_bytes(std::span<const Tet> tets, std::size_t first,
                         std::span<const int> regions);

}  // namespace pdr::io::tetgen_lines
