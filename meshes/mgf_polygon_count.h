// SPDX-License-Identifier: Apache-2.0
// The polygons MGF statements would make, counted without making them: the reader
// (mgf_reader.cpp) asks before it runs an array, so that three lines asking for 10^8 spheres are
// refused at once rather than after building the polygons the limit allows. A surface counts its
// whole tessellation (mgf_shapes.h); fewer polygons are made only where corners coincide.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "meshes/mgf_file.h"

namespace hmcr {

// The polygons of one geometric entity (f, sph, cyl, cone, ring, torus, prism) at `segments`
// per circle; 0 for any other statement.
std::uint64_t mgf_entity_polygons(const std::vector<std::string>& words, int segments);

class MgfPolygonCount {
public:
    // The file an `i` statement of `from` names, read (or already read); throws InputError at
    // `where` when there is none.
    using Include = std::function<const MgfFile&(const MgfFile& from, const MgfStatement& i,
                                                 const std::string& where)>;

    MgfPolygonCount(int segments, Include include)
        : m_segments(segments), m_include(std::move(include)) {}

    // The polygons one run of statements [begin, end) of `file` makes, a balanced block, with
    // arrays and includes expanded; UINT64_MAX when there are more. Throws InputError for a
    // transformation that does not parse and an include that cannot be read, nests too deep or
    // includes itself. Blocks nest without recursion: nesting is limited where they run.
    std::uint64_t block(const MgfFile& file, std::size_t begin, std::size_t end);
    std::uint64_t whole(const MgfFile& file) { return block(file, 0, file.statements.size()); }

private:
    std::uint64_t count(const MgfFile& file, std::size_t begin, std::size_t end);
    std::uint64_t included(const MgfFile& from, const MgfStatement& i);

    int m_segments;
    Include m_include;
    // Counted blocks by file and first statement: a block's count does not depend on where it
    // runs, and arrays of arrays would otherwise count their inner blocks once per instance.
    std::map<std::pair<const MgfFile*, std::size_t>, std::uint64_t> m_counted;
    std::vector<std::filesystem::path> m_open;  // the files being counted, outermost first
};

}  // namespace hmcr
