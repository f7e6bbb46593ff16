// framefix::run: the stage order, where it stops, options checked first, progress forward only,
// no process-wide side effects.
#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "framefix/core/error.h"
#include "framefix/pipeline/correction_methods.h"
#include "framefix/pipeline/pipeline.h"
#include "framefix/pipeline/report.h"

namespace framefix {
namespace {

std::string sample(const std::string& name) { return std::string(FRAMEFIX_SAMPLES_DIR) + "/" + name + ".step"; }

constexpr double kCoarse = 1.6;  // size factor: a few thousand tets carry these facts

RunOptions coarse(Stage stop) {
    RunOptions o;
    o.stop_after = stop;
    o.size_factor = kCoarse;
    return o;
}

const std::vector<std::string> kOrder = {"load", "mesh", "field", "singularities", "correct", "blocks"};

int stage_index(const std::string& s) { return int(std::find(kOrder.begin(), kOrder.end(), s) - kOrder.begin()); }

TEST(Pipeline, StopsAfterTheStageItIsGiven) {
    const RunResult m = run(RunInput::file(sample("cube")), coarse(Stage::mesh));
    EXPECT_TRUE(m.mesh && m.model);
    EXPECT_FALSE(m.field || m.singularities || m.correction || m.blocks);
    EXPECT_EQ(m.mesh->features.curves(), 12);

    const RunResult f = run(RunInput::file(sample("cube")), coarse(Stage::field));
    ASSERT_TRUE(f.field);
    EXPECT_FALSE(f.singularities);
    EXPECT_EQ(f.field->frames.axes.rows(), f.mesh->tets.num_vertices());

    const RunResult s = run(RunInput::file(sample("cube")), coarse(Stage::singularities));
    ASSERT_TRUE(s.singularities);
    EXPECT_EQ(s.singularities->summary.curves, 0);  // a cube has no singular curve
    EXPECT_FALSE(s.correction || s.blocks);
}

TEST(Pipeline, NoCorrectionSkipsTheStageButNotTheBlocks) {
    RunOptions o = coarse(Stage::blocks);
    o.correction = kNoCorrection;
    const RunResult r = run(RunInput::file(sample("cube")), o);
    EXPECT_FALSE(r.correction);
    ASSERT_TRUE(r.blocks);
    EXPECT_EQ(r.blocks->count, 1);
}

TEST(Pipeline, CorrectionKeepsTheGraphItCorrected) {
    RunOptions o;
    o.stop_after = Stage::correction;
    o.correction = "snap";
    const RunResult r = run(RunInput::file(sample("notch")), o);
    ASSERT_TRUE(r.correction);
    EXPECT_EQ(r.correction->method, "snap");
    EXPECT_TRUE(r.correction->changed);
    EXPECT_EQ(r.correction->before.curves_3_5, 1);  // the notch's one 3-5 curve...
    EXPECT_EQ(r.correction->graph_before.summary.curves_3_5, 1);
    EXPECT_EQ(r.singularities->summary.curves_3_5, 0);  // ...snapped away
    EXPECT_TRUE(r.field->constraints.kind == r.correction->snap.constraints.kind);  // solved under the snap
}

TEST(Pipeline, UnavailableOrUnknownMethodsAreRefusedBeforeLoading) {
    for (const CorrectionMethod& m : correction_methods()) {
        if (m.available) continue;
        RunOptions o;
        o.stop_after = Stage::correction;
        o.correction = m.name;
        bool loaded = false;
        o.progress = [&](const std::string&, double) { loaded = true; };
        try {
            run(RunInput::file("/nonexistent/part.step"), o);
            FAIL() << m.name << " was not refused";
        } catch (const Error& e) {
            EXPECT_EQ(e.stage(), "correct");
            EXPECT_NE(e.message().find("not available yet"), std::string::npos) << e.message();
        }
        EXPECT_FALSE(loaded);
    }
    RunOptions o;
    o.stop_after = Stage::blocks;
    o.correction = "magic";
    EXPECT_THROW(run(RunInput::file("/nonexistent/part.step"), o), Error);
}

TEST(Pipeline, AMethodIsOnlyCheckedWhenTheRunReachesTheCorrection) {
    RunOptions o = coarse(Stage::mesh);
    o.correction = "magic";
    EXPECT_NO_THROW(run(RunInput::file(sample("cube")), o));
}

TEST(Pipeline, ProgressGoesForwardInStageOrder) {
    RunOptions o = coarse(Stage::blocks);
    std::vector<std::pair<int, double>> lines;
    o.progress = [&](const std::string& stage, double f) { lines.push_back({stage_index(stage), f}); };
    run(RunInput::file(sample("l_prism")), o);
    ASSERT_FALSE(lines.empty());
    for (size_t i = 1; i < lines.size(); ++i)
        EXPECT_GE(lines[i], lines[i - 1]) << kOrder[lines[i].first] << " " << lines[i].second << " after "
                                          << kOrder[lines[i - 1].first] << " " << lines[i - 1].second;
    std::vector<int> seen;
    for (const auto& l : lines)
        if (seen.empty() || seen.back() != l.first) seen.push_back(l.first);
    EXPECT_EQ(seen, (std::vector<int>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(lines.back(), std::make_pair(5, 1.0));
}

TEST(Pipeline, ThreadCountIsPerCall) {
    const int before = omp_get_max_threads();
    RunOptions one = coarse(Stage::singularities), two = one;
    one.threads = 1;
    two.threads = 2;
    const RunResult a = run(RunInput::file(sample("notch")), one);
    EXPECT_EQ(omp_get_max_threads(), before);  // the host process keeps its own setting
    const RunResult b = run(RunInput::file(sample("notch")), two);
    EXPECT_EQ(a.field->frames.coefficients, b.field->frames.coefficients);  // deterministic
    EXPECT_EQ(a.singularities->summary.curves, b.singularities->summary.curves);
}

TEST(Pipeline, AShapeRunsLikeItsFile) {
    const RunResult file = run(RunInput::file(sample("l_prism")), coarse(Stage::mesh));
    const RunResult shape = run(RunInput::shape(*file.model), coarse(Stage::mesh));
    EXPECT_EQ(shape.input_path, file.input_path);
    EXPECT_EQ(shape.mesh->tets.num_tets(), file.mesh->tets.num_tets());
    EXPECT_EQ(shape.mesh->features.curves(), 18);
}

TEST(Pipeline, ReportHasASectionPerStageReached) {
    const std::string mesh = report_json(run(RunInput::file(sample("cube")), coarse(Stage::mesh)));
    EXPECT_NE(mesh.find("\"features\""), std::string::npos);
    EXPECT_EQ(mesh.find("\"singularities\""), std::string::npos);
    EXPECT_EQ(mesh.find("\"field\""), std::string::npos);
}

TEST(CorrectionRegistry, ListsAutoThenThePapersFourMethods) {
    const auto& all = correction_methods();
    ASSERT_EQ(all.size(), 5u);
    EXPECT_EQ(all[0].name, "auto");  // the default
    EXPECT_TRUE(all[0].available && !all[0].apply);  // correct() runs it through correct_auto
    for (const auto& m : all) {
        EXPECT_FALSE(m.description.empty()) << m.name;
        EXPECT_TRUE(m.available) << m.name;
        EXPECT_EQ(m.apply == nullptr, m.name == "auto") << m.name;
        EXPECT_TRUE(m.never_worse) << m.name;  // issue 15: every method
    }
    EXPECT_EQ(RunOptions{}.correction, "auto");
    const char* order[] = {"auto", "snap", "fillet", "extrude-curves", "extrude-nodes"};
    for (size_t k = 0; k < all.size(); ++k) EXPECT_EQ(&find_correction_method(order[k]), &all[k]);
    EXPECT_THROW(find_correction_method("chamfer"), Error);
}

TEST(Stage, NamesAreTheProgressNames) {
    EXPECT_STREQ(stage_name(Stage::load), "load");
    EXPECT_STREQ(stage_name(Stage::correction), "correct");
    EXPECT_STREQ(stage_name(Stage::blocks), "blocks");
}

}  // namespace
}  // namespace framefix
