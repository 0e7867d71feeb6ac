// Section readers of the Gmsh MSH formats (internal to pdr_io). Each is called with the
// scanner on the section's opening line ("$Nodes") and returns with it on the closing line
// ("$EndNodes"), which it checks. Binary data starts right after the opening line (or
// after the 2.2 count line) and is read with a ByteReader; the scanner then resumes after
// it. See gmsh.hpp for what is read.
#pragma once

#include <cstddef>
#include <map>
#include <string_view>
#include <utility>

#include "io/gmsh_common.hpp"
#include "io/text_scanner.hpp"

namespace pdr::io {

struct GmshFormat {
  int major = 0;               // 2 or 4
  bool binary = false;
  std::size_t data_size = 8;   // size_t width in 4.1 binary
};

// (entity dimension, entity tag) -> first physical tag (only entities that have one).
using GmshPhysicals = std::map<std::pair<int, int>, int>;

// $PhysicalNames (both versions): "<n>" then n lines "<dim> <tag> \"<name>\"". Returns
// (dim, physical tag) -> marker for the groups named "pdr marker <marker>" (gmsh.hpp).
GmshMarkerNames read_physical_names(TextScanner& s);

// Moves to the next line and checks that it is "$End<name>".
void expect_section_end(TextScanner& s, std::string_view name);

void read_nodes_v2(TextScanner& s, const GmshFormat& f, GmshNodes& nodes);
void read_elements_v2(TextScanner& s, const GmshFormat& f, const GmshNodes& nodes,
                      GmshSink& sink);

void read_entities_v4(TextScanner& s, const GmshFormat& f, GmshPhysicals& physicals);
void read_nodes_v4(TextScanner& s, const GmshFormat& f, GmshNodes& nodes);
void read_elements_v4(TextScanner& s, const GmshFormat& f, const GmshNodes& nodes,
                      const GmshPhysicals& physicals, GmshSink& sink);

// Maps `tag` through `nodes`, failing with `fail(message)` when it is not defined.
template <class Fail>
std::uint32_t map_node(const GmshNodes& nodes, std::uint64_t tag, std::int64_t element,
                       Fail&& fail) {
  const std::uint32_t i = nodes.find(tag);
  if (i == GmshNodes::kMissing)
    fail("element " + std::to_string(element) + " uses node " + std::to_string(tag) +
         ", which $Nodes does not define; the file is inconsistent, export it again");
  return i;
}

}  // namespace pdr::io
