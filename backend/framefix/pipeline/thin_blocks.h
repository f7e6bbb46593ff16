#pragma once
// Blocks thinner than the tet mesh resolves (docs/algorithms.md#thin-blocks): where a singular
// curve runs closer than 3 h to the boundary, the block between them is 1-2 tets thick and the
// partition cannot carve it. The run meshes the part again, finer on the faces next to such
// curves, and keeps the finer blocks when they are better.
#include <functional>
#include <map>

#include "framefix/mesh/tet_mesh.h"
#include "framefix/pipeline/pipeline.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {

// Blocks at least this many mean edge lengths thick are resolved (docs/algorithms.md#block-validation).
constexpr double kResolvedThicknessH = 3;

struct ThinFaces {
    std::map<int, double> face_size;  // B-rep face (1-based) -> edge length that resolves its thin blocks
    double thinnest = 0;              // smallest curve-to-boundary distance seen, model units (0: none)
};

// For each B-rep face: the smallest distance d < 3 h from a singular curve's interior points to
// it, as the size d / 3 (no finer than h / 3). Points within 1.5 h of a curve's boundary end (the
// curve entering the surface) and points within 0.5 h of the boundary (a curve on it) do not count,
// nor points whose singular triangle (a topology face id) `counts` rejects (null: all count).
ThinFaces thin_block_faces(const TetMesh& mesh, const SingularityGraph& graph, double h,
                           const std::function<bool(int)>& counts = {});

// Tets of the part meshed again with `thin`'s face sizes: the mesh's own plus a band about 3 of
// the finer edges deep over each finer face (TetGen's grading spreads the rest).
double estimate_thin_tets(const TetMesh& mesh, const ThinFaces& thin);

// After the blocks stage of `r` (run with `options`): when its blocks are not all valid and
// conforming, its graph is hex-meshable and thin_block_faces finds faces within the tet budget
// (at most 4.6 x the tets), the whole run again from the mesh stage with those face sizes. The
// finer run's mesh, field, graph, correction and blocks replace r's when its blocks are better.
// Never throws for the finer run's failures: the reason says what failed and r stands.
ThinRefinement refine_thin_blocks(const RunOptions& options, RunResult& r);

}  // namespace framefix
