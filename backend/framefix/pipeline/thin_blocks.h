#pragma once
// Blocks thinner than the tet mesh resolves (docs/algorithms.md#thin-blocks): where a singular
// curve, or a sheet parallel to the boundary, runs closer than 3 h to the boundary, the block
// between them is 1-2 tets thick and the partition cannot carve it. The run meshes the part again
// with shorter edges on the faces there, and keeps the finer blocks when they are better.
#include <functional>
#include <map>

#include "framefix/blocks/blocks.h"
#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"
#include "framefix/pipeline/pipeline.h"
#include "framefix/singularities/singularity_graph.h"

namespace framefix {

// Blocks at least this many mean edge lengths thick are resolved (docs/algorithms.md#block-validation).
constexpr double kResolvedThicknessH = 3;

struct ThinFaces {
    std::map<int, double> face_size;  // B-rep face (1-based) -> edge length that resolves its thin blocks
    int places = 0;                   // thin places counted (curve points, sheet triangles)
    double thinnest = 0;              // smallest distance to the boundary counted, model units (0: none)
};

// Thin places, at a distance d < 3 h from the nearest boundary triangle, each asking for edges of
// d / 3 (no shorter than h / 3) on a B-rep face:
// - singular-curve points, except within 1.5 h of the curve's boundary end (where a curve enters
//   the surface it is not a thin block): every face within 3 h, at its own distance;
// - sheet triangles whose normal is within 30 degrees of the nearest boundary triangle's (a sheet
//   parallel to the wall: a cushion under it): that triangle's face.
// Places within 0.5 h of the boundary (a curve or sheet on it) do not count, nor places `counts`
// rejects (null: all count).
ThinFaces thin_block_faces(const TetMesh& mesh, const SingularityGraph& graph, const SheetSoup& sheets, double h,
                           const std::function<bool(const Eigen::Vector3d&)>& counts = {});

// Under-faced invalid blocks (fewer than 6 faces) no thicker than kResolvedThicknessH h, such as
// a slab between two parallel sheets 1-2 h apart whose narrow end faces the staircase frays away:
// every B-rep face the block touches asks for edges of a third of its thickness (no shorter than
// h / 3). Adds to `thin`.
void add_thin_blocks(const TetMesh& mesh, const TetTopology& topo, const BlockDecomposition& blocks, double h,
                     ThinFaces& thin);

// Tets of the part meshed again with `thin`'s face sizes: the mesh's own plus a band about 1.4 of
// the finer edges deep over each finer face (TetGen's grading spreads the rest).
double estimate_thin_tets(const TetMesh& mesh, const ThinFaces& thin);

// Whether a finer run's blocks replace the first run's: fewer 3-5 curves plus invalid nodes first
// (blocks all valid and conforming around a 3-5 curve are no hex mesh: notch_shallow at 1.5 x),
// then all valid and conforming, then valid minus invalid blocks, then conforming minus other
// pairs.
bool finer_run_better(const RunResult& finer, const RunResult& first);

// After the blocks stage of `r` (run with `options`): when its blocks are not all valid and
// conforming, its graph is hex-meshable and thin_block_faces finds thin places next to invalid
// blocks within the tet budget (at most 6 x the tets), the whole run again from the mesh stage
// with those face sizes. The finer run's mesh, field, graph, correction and blocks replace r's when
// its blocks are better; when they are still not all valid and conforming, once more from them
// (options.thin_rounds), with their thin blocks (add_thin_blocks) too. Never throws for the finer
// run's failures: the reason says what failed.
ThinRefinement refine_thin_blocks(const RunOptions& options, RunResult& r);

}  // namespace framefix
