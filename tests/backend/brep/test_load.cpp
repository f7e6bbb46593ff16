#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "fixtures.h"
#include "framefix/brep/brep_model.h"
#include "framefix/core/error.h"

namespace framefix {
namespace {

using test::bad_input;
using test::sample;

// The Error thrown by f(), or a failure naming what was expected.
template <class F>
Error error_of(F f) {
    try {
        f();
    } catch (const Error& e) {
        return e;
    }
    ADD_FAILURE() << "no framefix::Error thrown";
    return Error("none", "");
}

TEST(Load, CubeStepHasBoxTopology) {
    const BrepModel m = load_shape(sample("cube"));
    EXPECT_EQ(m.kind, "step");
    EXPECT_EQ(m.num_faces, 6);
    EXPECT_EQ(m.num_edges, 12);
    EXPECT_EQ(m.num_vertices, 8);
    EXPECT_NEAR(m.volume, 1.0, 1e-9);
    EXPECT_NEAR((m.bbox_max - m.bbox_min).norm(), std::sqrt(3.0), 1e-6);
}

TEST(Load, EverySampleIsOneValidSolid) {
    for (const char* name : {"cube", "cylinder", "l_prism", "notch", "box_arc", "box_arc_curved",
                             "half_sphere_box", "groove", "two_cylinders"}) {
        const BrepModel m = load_shape(sample(name));
        EXPECT_GT(m.volume, 0) << name;
        EXPECT_GT(m.num_faces, 0) << name;
    }
}

TEST(Load, BrepStringRoundTripKeepsIndices) {
    const BrepModel a = load_shape(sample("notch"));
    const BrepModel b = load_brep_string(to_brep_string(a));
    EXPECT_EQ(b.kind, "brep");
    EXPECT_TRUE(b.path.empty());
    EXPECT_EQ(b.num_faces, a.num_faces);
    EXPECT_EQ(b.num_edges, a.num_edges);
    EXPECT_NEAR(b.volume, a.volume, 1e-9);
    EXPECT_TRUE(vertex_points(a).isApprox(vertex_points(b)));
}

TEST(Load, BrepFileAndStepAgree) {
    const BrepModel m = test::box(1, 2, 3);
    EXPECT_NEAR(m.volume, 6.0, 1e-9);
    EXPECT_EQ(m.num_edges, 12);
}

TEST(LoadErrors, MissingFile) {
    const Error e = error_of([] { load_shape("/nonexistent/part.step"); });
    EXPECT_EQ(e.stage(), "load");
    EXPECT_NE(e.message().find("/nonexistent/part.step does not exist"), std::string::npos) << e.what();
}

TEST(LoadErrors, EmptyFile) {
    const Error e = error_of([] { load_shape(bad_input("empty.step")); });
    EXPECT_NE(e.message().find("empty.step is empty"), std::string::npos) << e.what();
}

TEST(LoadErrors, TruncatedStep) {
    const Error e = error_of([] { load_shape(bad_input("truncated.step")); });
    EXPECT_EQ(e.stage(), "load");
    EXPECT_NE(e.message().find("truncated.step"), std::string::npos) << e.what();
}

TEST(LoadErrors, GarbageStep) {
    const Error e = error_of([] { load_shape(bad_input("garbage.step")); });
    EXPECT_NE(e.message().find("garbage.step is not a readable STEP file"), std::string::npos) << e.what();
}

TEST(LoadErrors, UnknownExtension) {
    const std::string path = testing::TempDir() + "part.obj";
    std::ofstream(path) << "v 0 0 0\n";
    const Error e = error_of([&] { load_shape(path); });
    EXPECT_NE(e.message().find("unknown extension '.obj'"), std::string::npos) << e.what();
}

TEST(LoadErrors, TwoSolids) {
    const Error e = error_of([] { load_shape(bad_input("two_solids.step")); });
    EXPECT_NE(e.message().find("two_solids.step contains 2 solids; export or select exactly one solid"),
              std::string::npos)
        << e.what();
}

TEST(LoadErrors, OpenShell) {
    const Error e = error_of([] { load_shape(bad_input("open_shell.brep")); });
    EXPECT_NE(e.message().find("open_shell.brep contains an open shell"), std::string::npos) << e.what();
}

TEST(LoadErrors, SingleFace) {
    const Error e = error_of([] { load_shape(bad_input("face.brep")); });
    EXPECT_NE(e.message().find("face.brep contains no solid but 0 shells, 1 face"), std::string::npos) << e.what();
}

TEST(LoadErrors, EmptyAndGarbageBrepStrings) {
    EXPECT_NE(error_of([] { load_brep_string(""); }).message().find("BREP string is empty"), std::string::npos);
    const Error e = error_of([] { load_brep_string("CASCADE Topology V1, (c) Matra-Datavision\nnonsense"); });
    EXPECT_EQ(e.stage(), "load");
    EXPECT_NE(e.message().find("BREP string"), std::string::npos) << e.what();
}

TEST(LoadErrors, TruncatedBrepString) {
    const std::string text = to_brep_string(load_shape(sample("cube")));
    const Error e = error_of([&] { load_brep_string(text.substr(0, text.size() / 2)); });
    EXPECT_EQ(e.stage(), "load");
}

}  // namespace
}  // namespace framefix
