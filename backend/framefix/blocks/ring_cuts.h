#pragma once
// Rings among the blocks (docs/algorithms.md#ring-cuts): a tube, a washer or a torus has no
// singular curve across its ring, so no sheet of the graph cuts it, and the partition leaves a
// solid torus (boundary Euler characteristic 0) that no hexahedron maps onto. Each gets meridian
// sheets at quarter turns of its core loop. Internal to blocks.
#include <vector>

#include "framefix/blocks/blocks.h"
#include "framefix/blocks/sheet_sources.h"
#include "framefix/streamlines/streamlines.h"

namespace framefix {

// Meridian cuts per ring: 3 is the fewest that leaves every pair of neighbours one shared face;
// 4 turns each block by 90 degrees, as the blocks of a cylinder's O-grid.
constexpr int kRingCuts = 4;

// For each block with a manifold boundary of Euler characteristic 0 (its boundary triangles in
// `surface`): the vertex deepest inside it (most mesh edges from its boundary), the field axis
// whose streamline from there comes back within 2 h of it (the ring's core loop; none: no cut),
// and at kRingCuts equal steps along that loop a source: the streamline through the point along a
// second axis, to the boundary both ways, seeded every h, its sheets along the third axis both
// ways. Each source's name is "ring:<block>".
std::vector<SheetSource> ring_sources(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                                      const BlockDecomposition& blocks,
                                      const std::vector<std::vector<BoundaryTriangle>>& surface, double h,
                                      const TraceOptions& trace);

}  // namespace framefix
