#pragma once
// Vertex renumbering for the solver's memory locality. gmsh numbers vertices far apart (notch,
// 230k tets: 71 % of the stiffness entries couple rows > 4096 apart), so every SpMV of the CG
// misses the cache on most neighbours. The solver runs on a reverse Cuthill-McKee numbering and
// maps its results back. Internal to frame_field.
#include <vector>

#include "framefix/frame_field/constrained_space.h"
#include "framefix/frame_field/p1_system.h"

namespace framefix {

// order[new] = old. Deterministic (ties broken by degree, then index); one BFS tree per
// connected component, each started from a pseudo-peripheral vertex.
std::vector<int> rcm_order(const P1System& sys);

// The same system / space with row new = row order[new] of the input.
P1System permute(const P1System& sys, const std::vector<int>& order);
ConstrainedSpace permute(const ConstrainedSpace& space, const std::vector<int>& order);

}  // namespace framefix
