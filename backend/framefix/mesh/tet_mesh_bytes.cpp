// A TetMesh as bytes, to bring it back from the worker process TetGen runs in.
#include "framefix/core/bytes.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {
namespace {

// Every array of the mesh, in one order for writing and reading.
template <class Mesh, class F>
void each_array(Mesh& m, F&& f) {
    f(m.points);
    f(m.tets);
    f(m.boundary_faces);
    f(m.face_tags);
    f(m.feature_edges);
    f(m.edge_tags);
    f(m.corner_vertices);
}

}  // namespace

std::string tet_mesh_bytes(const TetMesh& m) {
    ByteWriter w;
    each_array(m, [&](const auto& a) { w.matrix(a); });
    w.value(m.size);
    return w.take();
}

TetMesh tet_mesh_from_bytes(const std::string& bytes) {
    ByteReader r(bytes);
    TetMesh m;
    each_array(m, [&](auto& a) { r.matrix(a); });
    m.size = r.value<double>();
    FF_ASSERT(r.done());
    return m;
}

}  // namespace framefix
