#pragma once
// Singular triangles -> curves and nodes (docs/algorithms.md#chains, #chain-ends-and-nodes).
// Internal to singularities/, exposed for the tests, which feed it hand-made face labels.
//
// - A tet with exactly two singular faces (neither complex) links them: the curve passes through.
// - Node tets (>= 3 singular faces, or any complex face) clustered by shared vertices are junctions.
// - A chain end is: a boundary triangle (boundary end), a face of a junction tet (junction end),
//   or a face whose tet has no other singular face (dead end). A dead end joins the nearest
//   junction within attach_distance; else, if its tet touches the boundary, it is a boundary end;
//   else dead ends closer than attach_distance share one interior node (a curve ending inside,
//   invalid unless two such ends heal a gap).
// - Junk: a chain of <= 2 faces with both ends at the same junction is dropped.
// - An interior node where exactly two curve ends meet is no node: the two curves are joined
//   through it (a 3-5 transition at a spurious junction then stays one 3-5 curve).
#include <vector>

#include <Eigen/Core>

#include "framefix/mesh/tet_mesh.h"
#include "framefix/mesh/tet_topology.h"

namespace framefix {

struct ChainOptions {
    double attach_distance = 3;  // dead-end attachment radius, in mean edge lengths
};

struct ChainNode {
    Eigen::Vector3d position = Eigen::Vector3d::Zero();  // model units
    bool boundary = false;
    std::vector<int> tets;            // junction tets (sorted), empty for boundary and dead-end nodes
    std::vector<int> boundary_faces;  // boundary nodes: the singular boundary triangles ending here
    std::vector<int> verts;           // boundary nodes: boundary vertices of the curve ends (sorted)
    int n_complex = 0;                // complex triangles (edges) inside the junction
    bool axes_normal = true;          // edge chains, boundary nodes: end edges' axes along the normal
    bool crossing = false;            // added where a curve passes another just before the boundary
};

struct ChainCurve {
    std::vector<int> faces;           // singular triangles in chain order (topology face ids)
    std::vector<Eigen::Vector3d> points;  // raw polyline: end node, face centroids, end node;
                                          // closed curves list each point once (cyclic)
    std::vector<int> face_point;      // #faces: index in `points` of each face's centroid
    bool closed = false;
    int ends[2] = {-1, -1};           // node ids, -1 for closed curves
};

struct ChainGraph {
    std::vector<ChainCurve> curves;
    std::vector<ChainNode> nodes;     // only nodes with at least one curve end
    double h_mean = 0;                // mean mesh edge length, model units
    int junk_chains = 0;              // dropped loops: <= 2 triangles, or close to their node
    int dead_ends = 0;                // chain ends in a tet with a single singular face
    int dead_ends_attached = 0;       // of which joined to a junction
    int joined = 0;                   // pass-through nodes removed by joining two curve ends
    int crossings = 0;                // nodes added at crossings near the boundary (join_crossings)
};

// face_valence: #F (topology faces) 0 regular, 3, 5 or -1 complex.
ChainGraph trace_chains(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& face_valence,
                        const ChainOptions& options = {});

}  // namespace framefix
