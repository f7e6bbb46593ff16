#pragma once
// Prism blocks cut into hexahedra (docs/algorithms.md#prism-cuts). Internal to blocks.
#include <array>
#include <optional>
#include <vector>

#include "framefix/blocks/validation.h"

namespace framefix {

// A block whose faces are two n-gon caps and n quads around them, n != 4: an n-gon extruded.
struct Prism {
    int n = 0;
    int caps[2] = {-1, -1};               // patch ids
    std::vector<int> laterals;            // patch ids in cyclic order
    std::vector<std::array<int, 2>> edge;  // edge[i]: the two corners laterals i - 1 and i share
};

// The prism structure of a validated block's patches, if it has one with min_n to 8 sides.
std::optional<Prism> prism_of(const BlockFaces& faces, const BlockInfo& info, int min_n = 5);

// Which side of a cut each lateral face of a prism falls on: 0, 1, or 2 for the one face cut
// across its middle. A cut runs from one lateral edge to another (even n) or to the middle of a
// lateral face (odd n).
std::vector<std::vector<int>> prism_cut_sides(const Prism& prism);

// Whether the lateral face a cut runs across (side 2) is shared with another block, which the cut
// then splits too.
bool cuts_a_neighbour_across(const Prism& prism, const std::vector<int>& side, const std::vector<int>& face_label);

// Each block that is an n-gonal prism (caps of 5 to 8 corners) is cut into hexahedra, one cut
// per round, where the blocks then have more valid blocks, no valid block lost and no more
// non-conforming pairs. At most options.prism_rounds cuts. `group`: the surface group of every
// topology face. Updates `out` (prism_cuts) and its validation `v`.
void cut_prisms(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                const BlockOptions& options, BlockDecomposition& out, Validated& v);

}  // namespace framefix
