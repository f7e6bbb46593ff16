#include "framefix/pipeline/block_stage.h"

#include "framefix/core/error.h"

namespace framefix {

BlockDecomposition decompose(const AnalysisResult& r, const Correction* correction, const AnalysisOptions& analysis,
                             const BlockOptions& options) {
    if (!r.has_singularities) throw InternalError("decompose: analyse before building blocks");
    report(analysis.progress, "blocks", 0.0);
    BlockOptions o = options;
    if (o.threads == 0) o.threads = analysis.threads;
    static const std::vector<SnappedPath> no_paths;
    const auto& paths = correction ? correction->snap.paths : no_paths;
    BlockDecomposition b = build_blocks(r.mesh, r.topology, r.features, r.field, r.singularities, paths, o);
    report(analysis.progress, "blocks", 1.0);
    return b;
}

}  // namespace framefix
