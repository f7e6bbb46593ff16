#pragma once
// Triangular prism blocks made hexahedra by a flat corner (docs/algorithms.md#triangular-prisms).
// Internal to blocks.
#include "framefix/blocks/validation.h"

namespace framefix {

// Each invalid block that is a triangle extruded (a gusset's web, a wedge) with a side face on the
// part's boundary: that face is split along its middle into two block faces, so the triangle
// becomes a quad with a flat (180 degree) corner, which the hex mesh refines. Kept where the
// blocks gain a valid block, no non-conforming pair and score better. Updates `out`
// (triangle_folds) and its validation `v`; `group`: the surface group of every topology face.
void fold_triangle_prisms(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& group, double h,
                          const BlockOptions& options, BlockDecomposition& out, Validated& v);

}  // namespace framefix
