#pragma once
// Valence labels along one curve -> curve kind (docs/algorithms.md#3-5-detection). Internal to
// singularities/, exposed for the tests.
//
// Labels are smoothed by a majority window; an OPEN curve is a 3-5 curve iff the majority of its
// first k smoothed labels differs from that of its last k, k = min(3, n/3) (at least 1). No
// minimum run length: genuine 3-5 curves had minority parts of 2-5 triangles. A closed loop with
// mixed labels is an artefact of an unconverged field: kind Other, never 3-5.
#include <vector>

#include "framefix/singularities/singularity_graph.h"

namespace framefix {

// Majority of the window of `window` labels centred on each entry (truncated at the ends of an
// open curve, wrapped around a closed one); a tie keeps the entry's own label. Labels are 3 or 5.
std::vector<int> smooth_labels(const std::vector<int>& labels, int window, bool closed);

struct LabelClass {
    CurveKind kind = CurveKind::Valence3;
    int end_label[2] = {0, 0};  // majority label at each end (open curves), 3 or 5
    int transition = -1;        // 3-5 curves: index of the first label of the end-1 part
};

// forced_end: a known label (3 or 5) for an end of an open curve, 0 = read it from the labels.
LabelClass classify_labels(const std::vector<int>& labels, bool closed, int window, const int forced_end[2] = nullptr);

}  // namespace framefix
