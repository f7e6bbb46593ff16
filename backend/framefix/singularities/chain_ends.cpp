#include "framefix/singularities/chain_ends.h"

#include <algorithm>
#include <map>
#include <utility>

#include "framefix/core/error.h"

namespace framefix::detail {
namespace {

constexpr size_t kJunkFaces = 2;  // a chain this short cannot leave its node's tet star

std::vector<int> end_boundary_verts(const ChainContext& c, const RawEnd& e) {
    std::vector<int> v;
    if (e.tet < 0) {
        for (int k = 0; k < 3; ++k) v.push_back(c.topo.faces(e.face, k));
    } else {
        for (int k = 0; k < 4; ++k)
            if (c.topo.on_boundary[c.mesh.tets(e.tet, k)]) v.push_back(c.mesh.tets(e.tet, k));
    }
    return v;
}

// Where the curve visibly ends: the boundary triangle, the boundary part of a dead-end tet
// that touches the boundary, or the dead-end tet.
Eigen::Vector3d end_position(const ChainContext& c, const RawEnd& e) {
    if (e.type == EndType::Boundary) {
        if (e.tet < 0) return face_centroid(c.mesh, c.topo, e.face);
        Eigen::Vector3d p = Eigen::Vector3d::Zero();
        const std::vector<int> v = end_boundary_verts(c, e);
        for (int i : v) p += c.mesh.points.row(i).transpose();
        return p / double(v.size());
    }
    return tet_centroid(c.mesh, e.tet);
}

bool touches_boundary(const ChainContext& c, int t) {
    for (int k = 0; k < 4; ++k)
        if (c.topo.on_boundary[c.mesh.tets(t, k)]) return true;
    return false;
}

// A chain from a node back to the same node with at most two triangles, or from a boundary node
// back to it within one edge length of where it leaves: a kink of the field around one junction
// tet or one boundary vertex, not a curve (docs/algorithms.md#chain-ends-and-nodes). Longer loops
// at a junction are judged once joined (drop_junction_loops).
bool is_junk(const ChainContext& c, const RawChain& ch, double h) {
    const RawEnd &a = ch.ends[0], &b = ch.ends[1];
    if (ch.closed || a.type != b.type || a.group != b.group || a.type == EndType::Dead) return false;
    if (ch.faces.size() <= kJunkFaces) return true;
    if (a.type == EndType::Junction) return false;
    const Eigen::Vector3d at = end_position(c, a);
    for (int f : ch.faces)
        if ((face_centroid(c.mesh, c.topo, f) - at).norm() > h) return false;
    return true;
}

}  // namespace

std::vector<int> close_groups(const std::vector<Eigen::Vector3d>& points, double radius) {
    DisjointSet sets(int(points.size()));
    for (size_t i = 0; i < points.size(); ++i)
        for (size_t j = i + 1; j < points.size(); ++j)
            if ((points[i] - points[j]).norm() < radius) sets.unite(int(i), int(j));
    std::vector<int> groups;
    for (size_t i = 0; i < points.size(); ++i) groups.push_back(sets.find(int(i)));
    return groups;
}

EndStats resolve_ends(const ChainContext& c, double attach_radius, std::vector<RawChain>& chains) {
    EndStats stats;
    std::vector<std::pair<int, Eigen::Vector3d>> junction;  // (cluster, tet centroid) of node tets
    for (int t = 0; t < c.mesh.num_tets(); ++t)
        if (c.cluster[t] >= 0) junction.emplace_back(c.cluster[t], tet_centroid(c.mesh, t));

    std::vector<RawEnd*> dead;
    for (RawChain& ch : chains) {
        if (ch.closed) continue;
        for (RawEnd& e : ch.ends) {
            if (e.type != EndType::Dead) continue;
            ++stats.dead_ends;
            // Ring curves often stop one tet short of their junction (docs/algorithms.md#chain-ends-and-nodes).
            const Eigen::Vector3d p = tet_centroid(c.mesh, e.tet);
            double best = attach_radius;
            for (const auto& [cl, x] : junction) {
                const double d = (x - p).norm();
                if (d < best) best = d, e.group = cl;
            }
            if (e.group >= 0) {
                e.type = EndType::Junction;
                ++stats.attached;
            } else if (touches_boundary(c, e.tet)) {
                e.type = EndType::Boundary;  // the curve leaves through a boundary edge or vertex
            } else {
                dead.push_back(&e);
            }
        }
    }

    // Dead ends close together share a node, so that a curve with a gap can be joined again.
    std::vector<Eigen::Vector3d> at;
    for (const RawEnd* e : dead) at.push_back(tet_centroid(c.mesh, e->tet));
    const std::vector<int> groups = close_groups(at, attach_radius);
    for (size_t i = 0; i < dead.size(); ++i) dead[i]->group = groups[i];

    // Boundary ends sharing a vertex are one boundary node, unless the vertex lies on a B-rep
    // edge: ends on either side of a curve are in different faces, hence different surface
    // singularities (box_arc: the two ends of a short 3-5 curve straddle the imprinted arc).
    std::vector<char> on_curve(size_t(c.mesh.num_vertices()), 0);
    for (int e = 0; e < c.mesh.feature_edges.rows(); ++e) on_curve[c.mesh.feature_edges(e, 0)] = on_curve[c.mesh.feature_edges(e, 1)] = 1;
    std::vector<RawEnd*> bnd;
    for (RawChain& ch : chains)
        if (!ch.closed)
            for (RawEnd& e : ch.ends)
                if (e.type == EndType::Boundary) bnd.push_back(&e);
    DisjointSet bnd_sets(int(bnd.size()));
    std::map<int, int> first_end;  // boundary vertex -> first end touching it
    for (size_t i = 0; i < bnd.size(); ++i)
        for (int v : end_boundary_verts(c, *bnd[i])) {
            if (on_curve[v]) continue;
            auto [it, inserted] = first_end.emplace(v, int(i));
            if (!inserted) bnd_sets.unite(it->second, int(i));
        }
    for (size_t i = 0; i < bnd.size(); ++i) bnd[i]->group = bnd_sets.find(int(i));
    return stats;
}

void assemble(const ChainContext& c, const std::vector<RawChain>& chains, ChainGraph& graph) {
    std::map<std::pair<int, int>, int> node_of;  // (end type, group) -> node
    std::vector<Eigen::Vector3d> sum;            // accumulated end positions (dead, boundary nodes)
    std::vector<int> count;
    auto node = [&](const RawEnd& e) {
        FF_ASSERT(e.group >= 0);
        auto [it, inserted] = node_of.emplace(std::make_pair(int(e.type), e.group), int(graph.nodes.size()));
        if (inserted) {
            graph.nodes.emplace_back();
            graph.nodes.back().boundary = e.type == EndType::Boundary;
            sum.push_back(Eigen::Vector3d::Zero());
            count.push_back(0);
        }
        ChainNode& n = graph.nodes[it->second];
        sum[it->second] += end_position(c, e);
        count[it->second] += 1;
        if (n.boundary) {
            if (e.tet < 0) n.boundary_faces.push_back(e.face);
            for (int v : end_boundary_verts(c, e)) n.verts.push_back(v);
        }
        return it->second;
    };

    std::vector<int> cluster_node(c.nclusters, -1);
    for (const RawChain& ch : chains) {
        if (is_junk(c, ch, graph.h_mean)) {
            ++graph.junk_chains;
            continue;
        }
        ChainCurve cc;
        cc.faces = ch.faces;
        cc.closed = ch.closed;
        if (!ch.closed)
            for (int k = 0; k < 2; ++k) {
                cc.ends[k] = node(ch.ends[k]);
                if (ch.ends[k].type == EndType::Junction) cluster_node[ch.ends[k].group] = cc.ends[k];
            }
        graph.curves.push_back(std::move(cc));
    }

    // Node geometry: junctions from their tets, the other nodes from their curve ends.
    for (size_t i = 0; i < graph.nodes.size(); ++i) graph.nodes[i].position = sum[i] / std::max(count[i], 1);
    std::vector<Eigen::Vector3d> jsum(c.nclusters, Eigen::Vector3d::Zero());
    for (int t = 0; t < c.mesh.num_tets(); ++t) {
        const int n = c.cluster[t] >= 0 ? cluster_node[c.cluster[t]] : -1;
        if (n < 0) continue;
        graph.nodes[n].tets.push_back(t);
        jsum[c.cluster[t]] += tet_centroid(c.mesh, t);
    }
    for (int cl = 0; cl < c.nclusters; ++cl)
        if (cluster_node[cl] >= 0) {
            ChainNode& n = graph.nodes[cluster_node[cl]];
            n.position = jsum[cl] / double(n.tets.size());
        }
    for (size_t f = 0; f < c.val.size(); ++f)
        if (c.val[f] == -1) {
            const int cl = c.cluster[c.topo.face_tets(int(f), 0)];
            if (cl >= 0 && cluster_node[cl] >= 0) graph.nodes[cluster_node[cl]].n_complex += 1;
        }
    for (ChainNode& n : graph.nodes) {
        std::sort(n.boundary_faces.begin(), n.boundary_faces.end());
        n.boundary_faces.erase(std::unique(n.boundary_faces.begin(), n.boundary_faces.end()), n.boundary_faces.end());
        std::sort(n.verts.begin(), n.verts.end());
        n.verts.erase(std::unique(n.verts.begin(), n.verts.end()), n.verts.end());
    }

    // Raw polylines: interior end nodes always (joining relies on it), boundary nodes when apart.
    const double eps = 1e-6 * graph.h_mean;
    for (ChainCurve& cc : graph.curves) {
        // Whether the node point adds anything next to the centroid of the chain's end face.
        auto wanted = [&](int node_id, int face) {
            if (node_id < 0) return false;
            const ChainNode& n = graph.nodes[node_id];
            return !n.boundary || (face_centroid(c.mesh, c.topo, face) - n.position).norm() > eps;
        };
        if (wanted(cc.ends[0], cc.faces.front())) cc.points.push_back(graph.nodes[cc.ends[0]].position);
        for (int f : cc.faces) {
            cc.face_point.push_back(int(cc.points.size()));
            cc.points.push_back(face_centroid(c.mesh, c.topo, f));
        }
        if (wanted(cc.ends[1], cc.faces.back())) cc.points.push_back(graph.nodes[cc.ends[1]].position);
    }
}

}  // namespace framefix::detail
