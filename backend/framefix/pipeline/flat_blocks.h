#pragma once
// Flat corners refined in the blocks (docs/algorithms.md#flat-corner-refinement-in-the-blocks):
// where every block is valid and conforming, the hex mesh's flat-edge template runs on them, and
// when its hexes are better the tets of each block it cut go to the parts, so that the blocks the
// run reports, shows and meshes are the refined ones.
#include "framefix/pipeline/pipeline.h"

namespace framefix {

// The hex mesh of the run's blocks (with the flat-edge refinement unless turned off), its
// boundary vertices on the solid the tets were made from.
HexMesh mesh_hexes(const RunResult& r, const RunOptions& o);

// After the blocks stage (and the thin refinement): r.blocks become the refined blocks when the
// template cut any and their tets validate as hexahedra meeting face to face. Never throws for
// what it cannot refine: the reason says why.
BlockRefinement refine_flat_blocks(const RunOptions& o, RunResult& r);

}  // namespace framefix
