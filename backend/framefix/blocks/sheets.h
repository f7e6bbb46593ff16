#pragma once
// Separatrix sheets as ribbons between neighbouring streamlines (docs/algorithms.md#sheets).
// Internal to blocks.
#include <vector>

#include "framefix/blocks/blocks.h"
#include "framefix/blocks/sheet_sources.h"
#include "framefix/streamlines/streamlines.h"

namespace framefix {

// All polylines of the singular curves used as sources, stacked (#S x 3, model units).
Points singular_points(const SingularityGraph& graph);

// Traces every seed direction, zips matching streamlines of consecutive seeds into ribbons,
// extends sheets 0.5 h past source ends on the boundary, continues them past their source with
// cross streamlines, and widens feature/snapped ribbons laterally by options.overshoot h.
SheetSoup build_sheets(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                       const std::vector<SheetSource>& sources, const Points& singular, double h,
                       const BlockOptions& options, SheetStats& stats);

}  // namespace framefix
