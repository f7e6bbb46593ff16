#pragma once
// Corner lines of concave-curve curtains (docs/algorithms.md#curtain-corners). Internal to blocks.
//
// A concave feature curve continues its faces into the solid as two sheets (curtains). Where a
// snapped path ends on a curved concave curve, the path's surface continues as the curtain, and
// the path's 90-degree turn of the hex layers continues with it: the curtain has a corner line,
// the streamline along the curtain from the path's end. On the curtain's concave side (away from
// the curve's centre of curvature) two sheets leave that line at 45 degrees to the curve's
// normal. The groove's inner curtain cuts the ring below the groove floor in three; the dome's
// base circle gives the four corners of an O-grid around the column below the dome.
#include <vector>

#include "framefix/blocks/sheet_sources.h"
#include "framefix/streamlines/feature_seeds.h"
#include "framefix/streamlines/streamlines.h"

namespace framefix {

// One source per end of a convex snapped path (`convex`, from convex_paths) on a curved concave
// curve of `concave` (FeatureSeeds; curves of other valences are skipped). A path that emits sheets itself
// carries them past its end already: seeds every h along the corner line, two fixed directions. `trace` traces
// the line (the sheets' step, stop distance and singular points).
std::vector<SheetSource> curtain_corner_sources(const TetMesh& mesh, const FrameField& field, const TetLocator& locator,
                                                const std::vector<FeatureSeeds>& concave,
                                                const std::vector<SnappedPath>& paths,
                                                const std::vector<char>& convex, double h,
                                                const TraceOptions& trace);

// The frame of a concave curve jumps at a convex path's foot, and the cross extension of its
// curtains would start a second, slightly shifted copy of the corner's sheets there (a 2 h thin
// block on half_sphere_box_large). Seeds of `sources` of kind Concave within `reach` of a
// corner line's start stop continuing their jumps.
void mute_jumps_near_corners(std::vector<SheetSource>& sources, const std::vector<SheetSource>& corners, double reach);

}  // namespace framefix
