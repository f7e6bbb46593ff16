// A TetMesh as bytes, to bring it back from the worker process TetGen runs in.
#include "framefix/core/bytes.h"
#include "framefix/mesh/tet_mesh.h"

namespace framefix {

std::string tet_mesh_bytes(const TetMesh& m) {
    ByteWriter w;
    w.matrix(m.points);
    w.matrix(m.tets);
    w.matrix(m.boundary_faces);
    w.matrix(m.face_tags);
    w.matrix(m.feature_edges);
    w.matrix(m.edge_tags);
    w.matrix(m.corner_vertices);
    w.value(m.size);
    return w.take();
}

TetMesh tet_mesh_from_bytes(const std::string& bytes) {
    ByteReader r(bytes);
    TetMesh m;
    r.matrix(m.points);
    r.matrix(m.tets);
    r.matrix(m.boundary_faces);
    r.matrix(m.face_tags);
    r.matrix(m.feature_edges);
    r.matrix(m.edge_tags);
    r.matrix(m.corner_vertices);
    m.size = r.value<double>();
    FF_ASSERT(r.done());
    return m;
}

}  // namespace framefix
