#pragma once
// Loading CAD solids and everything that needs OpenCASCADE: the only module that includes it.
// A BrepModel holds exactly one valid solid; loaders refuse anything else with a framefix::Error.
// A file whose only solid comes with loose shells, faces or edges (construction geometry, as in
// some HexMe files) loads that solid; face/edge/vertex indices are always those of the solid.
#include <memory>
#include <string>

#include <Eigen/Core>

#include "framefix/mesh/features.h"
#include "framefix/mesh/size_model.h"
#include "framefix/mesh/surface_mesh.h"
#include "framefix/mesh/types.h"

namespace framefix {

struct BrepModel {
    struct Shape;                        // wraps the TopoDS_Shape; defined in brep/ only
    std::shared_ptr<const Shape> shape;  // immutable: corrections build new models
    std::string path;                    // source file, empty for BREP strings
    std::string kind;                    // "step" | "brep" | "iges"
    int num_faces = 0, num_edges = 0, num_vertices = 0;  // TopExp::MapShapes counts
    Eigen::Vector3d bbox_min = Eigen::Vector3d::Zero(), bbox_max = Eigen::Vector3d::Zero();
    double volume = 0;                   // model units^3
};

BrepModel load_shape(const std::string& path);               // .step/.stp/.brep/.iges/.igs
BrepModel load_brep_string(const std::string& brep_text);    // FreeCAD's exportBrepToString()
std::string to_brep_string(const BrepModel& model);
// Writes the solid to `path` (.brep or .step); framefix::Error("output") on failure.
void write_shape(const BrepModel& model, const std::string& path);

struct FeatureOptions {
    int samples_per_edge = 9;       // points along each edge where the dihedral angle is measured
    double tangent_angle_deg = 30;  // |theta - 180| below this: not a feature (tangent-continuous)
};
FeatureSet classify_features(const BrepModel& model, const FeatureOptions& options = {});

// Positions of the B-rep vertices: row i is Vertex<i+1> (TetMesh::corner_vertices order).
Points vertex_points(const BrepModel& model);
// n >= 2 points of Edge<edge>, evenly spaced in its parameter, ends included.
Points edge_points(const BrepModel& model, int edge, int n);

// Distance from p to B-rep edge `edge` (1-based, Edge<i>) / face `face` (Face<i>), model units.
double distance_to_edge(const BrepModel& model, int edge, const Eigen::Vector3d& p);
double distance_to_face(const BrepModel& model, int face, const Eigen::Vector3d& p);
// Twice the face's area over its boundary length, model units: a strip's width, a disc's radius,
// half a square's side (a face's inradius when it is a tangential polygon).
double face_width(const BrepModel& model, int face);
Eigen::Vector3d closest_point_on_edge(const BrepModel& model, int edge, const Eigen::Vector3d& p);
// The point of Face<face>'s surface closest to p, for p within about a mesh size of the face.
Eigen::Vector3d closest_point_on_face(const BrepModel& model, int face, const Eigen::Vector3d& p);

// Size h for about `target_tets` near-uniform tets in this solid.
double default_size(const BrepModel& model, int target_tets = kDefaultTargetTets);

// Faces (1-based) that OCCT's self-interference test finds crossing another face or themselves;
// empty for a sound solid. Runs in a worker process; meant for the failure path (it is slow).
Eigen::VectorXi self_intersecting_faces(const BrepModel& model);

// OCCT surface triangulation with boundary edges near h, faces and feature segments tagged.
SurfaceMesh tessellate(const BrepModel& model, const FeatureSet& features, const MeshOptions& options);

}  // namespace framefix
