#include "framefix/hexmesh/hex_files.h"

#include <fstream>
#include <map>
#include <set>

#include "framefix/core/error.h"
#include "framefix/mesh/vtk_writer.h"

namespace framefix {

namespace {

constexpr int kVtkHexahedron = 12, kVtkQuadraticHexahedron = 25;
constexpr int kMshHex8 = 5, kMshHex20 = 17;
// gmsh's 20-node hex lists its edges in this order; ours (C3D20, VTK) is 01 12 23 30 45 56 67 74 04 15 26 37.
constexpr int kMshEdgeFromOurs[12] = {0, 3, 8, 1, 9, 2, 10, 11, 4, 7, 5, 6};
constexpr int kQuadEdges[4][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};

std::ofstream open_for_writing(const std::string& path) {
    std::ofstream out(path);
    if (!out) throw Error("output", "cannot write " + path);
    out.precision(12);
    return out;
}

void finish(std::ofstream& out, const std::string& path) {
    out.flush();
    if (!out) throw Error("output", "cannot write " + path);
}

// Nodes of element h: 8 corners, then its 12 edge midpoints at order 2 (C3D20 / VTK order).
std::vector<int> element_nodes(const HexMesh& m, size_t h) {
    std::vector<int> nodes(m.hexes[h].begin(), m.hexes[h].end());
    if (!m.midpoints.empty()) nodes.insert(nodes.end(), m.midpoints[h].begin(), m.midpoints[h].end());
    return nodes;
}

}  // namespace

void write_hex_vtk(const HexMesh& m, const std::string& path) {
    VtkGrid g;
    g.points = m.points;
    VtkArray block{"block", 1, {}}, sj{"scaled_jacobian", 1, {}};
    for (size_t h = 0; h < m.hexes.size(); ++h) {
        g.cells.push_back(element_nodes(m, h));
        g.cell_types.push_back(m.midpoints.empty() ? kVtkHexahedron : kVtkQuadraticHexahedron);
        block.data.push_back(m.hex_block[h]);
        sj.data.push_back(m.scaled_jacobian[h]);
    }
    g.cell_data = {block, sj};
    write_vtk(g, path, "FrameFix hex mesh (block id and minimum scaled Jacobian per hex)");
}

void write_hex_msh(const HexMesh& m, const std::string& path) {
    std::ofstream out = open_for_writing(path);
    const Eigen::Vector3d lo = m.points.colwise().minCoeff(), hi = m.points.colwise().maxCoeff();
    const long nv = long(m.points.rows()), nh = long(m.hexes.size());
    out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
    out << "$Entities\n0 0 0 1\n1 " << lo.x() << ' ' << lo.y() << ' ' << lo.z() << ' ' << hi.x() << ' ' << hi.y() << ' '
        << hi.z() << " 0 0\n$EndEntities\n";
    out << "$Nodes\n1 " << nv << " 1 " << nv << "\n3 1 0 " << nv << '\n';
    for (long v = 0; v < nv; ++v) out << v + 1 << '\n';
    for (long v = 0; v < nv; ++v) out << m.points(v, 0) << ' ' << m.points(v, 1) << ' ' << m.points(v, 2) << '\n';
    out << "$EndNodes\n$Elements\n1 " << nh << " 1 " << nh << "\n3 1 " << (m.midpoints.empty() ? kMshHex8 : kMshHex20) << ' '
        << nh << '\n';
    for (long h = 0; h < nh; ++h) {
        out << h + 1;
        for (int c = 0; c < 8; ++c) out << ' ' << m.hexes[size_t(h)][c] + 1;
        if (!m.midpoints.empty())
            for (int e = 0; e < 12; ++e) out << ' ' << m.midpoints[size_t(h)][kMshEdgeFromOurs[e]] + 1;
        out << '\n';
    }
    out << "$EndElements\n";
    finish(out, path);
}

void write_hex_inp(const HexMesh& m, const std::string& path) {
    std::ofstream out = open_for_writing(path);
    out << "** FrameFix hex mesh\n*NODE, NSET=NALL\n";
    for (Eigen::Index v = 0; v < m.points.rows(); ++v)
        out << v + 1 << ", " << m.points(v, 0) << ", " << m.points(v, 1) << ", " << m.points(v, 2) << '\n';
    out << "*ELEMENT, TYPE=" << (m.midpoints.empty() ? "C3D8" : "C3D20") << ", ELSET=EALL\n";
    for (size_t h = 0; h < m.hexes.size(); ++h) {
        const std::vector<int> nodes = element_nodes(m, h);
        out << h + 1;
        for (size_t k = 0; k < nodes.size(); ++k) out << (k == 15 ? ",\n" : ", ") << nodes[k] + 1;  // 16 entries a line at most
        out << '\n';
    }
    std::map<std::pair<int, int>, int> mid;  // hex edge -> its midpoint, for the face node sets
    for (size_t h = 0; h < m.midpoints.size(); ++h)
        for (int e = 0; e < 12; ++e)
            mid[std::minmax(m.hexes[h][kHexEdges[e][0]], m.hexes[h][kHexEdges[e][1]])] = m.midpoints[h][e];
    std::map<int, std::set<int>> on_face;
    for (size_t q = 0; q < m.boundary_quads.size(); ++q) {
        if (m.quad_face[q] <= 0) continue;
        auto& nodes = on_face[m.quad_face[q]];
        for (int e = 0; e < 4; ++e) {
            nodes.insert(m.boundary_quads[q][e]);
            const auto it = mid.find(std::minmax(m.boundary_quads[q][kQuadEdges[e][0]], m.boundary_quads[q][kQuadEdges[e][1]]));
            if (it != mid.end()) nodes.insert(it->second);
        }
    }
    for (const auto& [face, nodes] : on_face) {
        out << "*NSET, NSET=FACE" << face << '\n';
        int k = 0;
        for (int v : nodes) out << v + 1 << (++k % 16 == 0 || k == int(nodes.size()) ? "\n" : ", ");
    }
    finish(out, path);
}

}  // namespace framefix
