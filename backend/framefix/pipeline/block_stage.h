#pragma once
// The block decomposition stage: separatrix sheets of the (corrected) field cut the part into
// blocks, checked to be hexahedra that conform to each other.
#include "framefix/blocks/blocks.h"
#include "framefix/pipeline/correction.h"
#include "framefix/pipeline/pipeline.h"

namespace framefix {

// Blocks of an analysed (and, with `correction`, corrected) result; the snapped paths of a snap
// correction emit sheets like concave feature curves.
BlockDecomposition decompose(const AnalysisResult& r, const Correction* correction, const AnalysisOptions& analysis,
                             const BlockOptions& options = {});

}  // namespace framefix
