// `framefix info`: what a front end (the workbench, a script) needs to know before a run.
#include <nlohmann/json.hpp>

#include "framefix/mesh/size_model.h"
#include "framefix/pipeline/correction_methods.h"
#include "framefix/pipeline/report.h"

namespace framefix {

std::string info_json() {
    nlohmann::json methods = nlohmann::json::array(), block_methods = nlohmann::json::array();
    for (const auto& m : correction_methods()) {
        methods.push_back({{"name", m.name}, {"available", m.available}, {"description", m.description}});
        if (m.available) block_methods.push_back(m.name);
    }
    block_methods.push_back(kNoCorrection);
    nlohmann::json j = {{"version", 1},
                        {"default_target_tets", kDefaultTargetTets},
                        {"mean_tet_volume_h3", kMeanTetVolumePerH3},
                        {"correction_methods", methods},
                        {"block_methods", block_methods}};
    return j.dump(1);
}

}  // namespace framefix
