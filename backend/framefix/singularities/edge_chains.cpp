#include "framefix/singularities/edge_chains.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "framefix/core/disjoint_set.h"
#include "framefix/core/error.h"
#include "framefix/singularities/chain_ends.h"

namespace framefix {
namespace {

using detail::EndType;
using Axes = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;

const double kCos45 = std::sqrt(0.5);

struct VEnd {
    EndType type = EndType::Dead;
    int vertex = -1;  // last vertex of the chain
    int edge = -1;    // last edge of the chain
    int at = -1;      // boundary ends: the boundary vertex where the curve ends
    int group = -1;   // junction cluster, boundary group or dead group
};

struct VChain {
    std::vector<int> edges;
    bool closed = false;
    VEnd ends[2];
};

struct Context {
    const TetMesh& mesh;
    const TetTopology& topo;
    const std::vector<int>& val;
    std::vector<std::vector<int>> incident;  // #V singular edges at each vertex (complex too)
    std::vector<char> complex_at;            // #V vertex of a complex edge
    std::vector<int> cluster;                // #V junction cluster, -1 off node vertices
    int nclusters = 0;
};

Eigen::Vector3d point(const TetMesh& mesh, int v) { return mesh.points.row(v).transpose(); }

int other_end(const TetTopology& topo, int e, int v) { return topo.edges(e, 0) == v ? topo.edges(e, 1) : topo.edges(e, 0); }

bool is_pass(const Context& c, int v) { return c.incident[size_t(v)].size() == 2 && !c.complex_at[size_t(v)]; }

Context classify_vertices(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& val) {
    const int nv = mesh.num_vertices();
    Context c{mesh, topo, val, std::vector<std::vector<int>>(size_t(nv)), std::vector<char>(size_t(nv), 0),
              std::vector<int>(size_t(nv), -1), 0};
    for (int e = 0; e < int(val.size()); ++e) {
        if (val[size_t(e)] == 0) continue;
        for (int k = 0; k < 2; ++k) {
            c.incident[size_t(topo.edges(e, k))].push_back(e);
            c.complex_at[size_t(topo.edges(e, k))] |= val[size_t(e)] == -1;
        }
    }
    auto node_vertex = [&](int v) {
        return !topo.on_boundary[size_t(v)] && (c.incident[size_t(v)].size() >= 3 || c.complex_at[size_t(v)]);
    };
    DisjointSet uf(nv);
    for (int e = 0; e < topo.edges.rows(); ++e)
        if (node_vertex(topo.edges(e, 0)) && node_vertex(topo.edges(e, 1))) uf.unite(topo.edges(e, 0), topo.edges(e, 1));
    std::vector<int> id(size_t(nv), -1);
    for (int v = 0; v < nv; ++v) {
        if (!node_vertex(v)) continue;
        const int r = uf.find(v);
        if (id[size_t(r)] < 0) id[size_t(r)] = c.nclusters++;
        c.cluster[size_t(v)] = id[size_t(r)];
    }
    return c;
}

VEnd end_at(const Context& c, int v, int e) {
    VEnd end;
    end.vertex = v;
    end.edge = e;
    if (c.topo.on_boundary[size_t(v)]) {
        end.type = EndType::Boundary;
        end.at = v;
    } else if (c.cluster[size_t(v)] >= 0) {
        end.type = EndType::Junction;
        end.group = c.cluster[size_t(v)];
    }
    return end;
}

// From vertex v along edge e through pass vertices to the next end, or back to v (a loop).
VChain walk(const Context& c, int v, int e, std::vector<char>& used) {
    VChain ch;
    int cur = v;
    for (;;) {
        used[size_t(e)] = 1;
        ch.edges.push_back(e);
        const int u = other_end(c.topo, e, cur);
        if (!is_pass(c, u)) {
            ch.ends[1] = end_at(c, u, e);
            return ch;
        }
        const std::vector<int>& inc = c.incident[size_t(u)];
        const int next = inc[0] != e ? inc[0] : inc[1];
        if (used[size_t(next)]) {
            ch.closed = true;
            return ch;
        }
        cur = u, e = next;
    }
}

std::vector<VChain> walk_chains(const Context& c) {
    std::vector<char> used(c.val.size(), 0);
    std::vector<VChain> chains;
    for (int v = 0; v < c.mesh.num_vertices(); ++v) {
        if (c.incident[size_t(v)].empty() || is_pass(c, v)) continue;
        for (int e : c.incident[size_t(v)]) {
            if (used[size_t(e)] || c.val[size_t(e)] == -1) continue;
            VChain ch = walk(c, v, e, used);
            ch.ends[0] = end_at(c, v, e);
            chains.push_back(std::move(ch));
        }
    }
    for (int e = 0; e < int(c.val.size()); ++e)
        if (c.val[size_t(e)] != 0 && c.val[size_t(e)] != -1 && !used[size_t(e)])
            chains.push_back(walk(c, c.topo.edges(e, 0), e, used));
    return chains;
}

// The boundary vertex nearest to interior vertex v among the vertices of its tets, or -1.
int boundary_neighbour(const Context& c, int v) {
    int best = -1;
    double d = 0;
    for (int k = c.topo.vert_tets_start[size_t(v)]; k < c.topo.vert_tets_start[size_t(v) + 1]; ++k)
        for (int j = 0; j < 4; ++j) {
            const int u = c.mesh.tets(c.topo.vert_tets[size_t(k)], j);
            const double du = (point(c.mesh, u) - point(c.mesh, v)).norm();
            if (c.topo.on_boundary[size_t(u)] && (best < 0 || du < d)) best = u, d = du;
        }
    return best;
}

void resolve_dead_ends(const Context& c, double radius, std::vector<VChain>& chains, ChainGraph& graph) {
    std::vector<std::pair<int, Eigen::Vector3d>> junction;
    for (int v = 0; v < c.mesh.num_vertices(); ++v)
        if (c.cluster[size_t(v)] >= 0) junction.emplace_back(c.cluster[size_t(v)], point(c.mesh, v));
    std::vector<VEnd*> dead;
    for (VChain& ch : chains)
        for (VEnd& e : ch.ends) {
            if (ch.closed || e.type != EndType::Dead) continue;
            ++graph.dead_ends;
            double best = radius;
            for (const auto& [cl, x] : junction)
                if ((x - point(c.mesh, e.vertex)).norm() < best) best = (x - point(c.mesh, e.vertex)).norm(), e.group = cl;
            if (e.group >= 0) {
                e.type = EndType::Junction;
                ++graph.dead_ends_attached;
            } else if ((e.at = boundary_neighbour(c, e.vertex)) >= 0) {
                e.type = EndType::Boundary;
            } else {
                dead.push_back(&e);
            }
        }
    std::vector<Eigen::Vector3d> at;
    for (const VEnd* e : dead) at.push_back(point(c.mesh, e->vertex));
    const std::vector<int> groups = detail::close_groups(at, radius);
    for (size_t i = 0; i < dead.size(); ++i) dead[i]->group = groups[i];
}

// Boundary ends at one vertex, or at two vertices of a boundary triangle that are both off the
// feature curves (ends on either side of a curve belong to different faces), share a node.
void group_boundary_ends(const Context& c, std::vector<VChain>& chains) {
    std::vector<char> on_curve(size_t(c.mesh.num_vertices()), 0);
    for (int e = 0; e < c.mesh.feature_edges.rows(); ++e)
        on_curve[size_t(c.mesh.feature_edges(e, 0))] = on_curve[size_t(c.mesh.feature_edges(e, 1))] = 1;
    std::vector<VEnd*> ends;
    std::map<int, int> first_at;  // boundary vertex -> first end there
    for (VChain& ch : chains)
        for (VEnd& e : ch.ends)
            if (!ch.closed && e.type == EndType::Boundary) ends.push_back(&e);
    DisjointSet sets(int(ends.size()));
    for (size_t i = 0; i < ends.size(); ++i) {
        auto [it, inserted] = first_at.emplace(ends[i]->at, int(i));
        if (!inserted) sets.unite(it->second, int(i));
    }
    for (int f = 0; f < c.mesh.boundary_faces.rows(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int a = c.mesh.boundary_faces(f, k), b = c.mesh.boundary_faces(f, (k + 1) % 3);
            const auto ia = first_at.find(a), ib = first_at.find(b);
            if (ia != first_at.end() && ib != first_at.end() && !on_curve[size_t(a)] && !on_curve[size_t(b)])
                sets.unite(ia->second, ib->second);
        }
    for (size_t i = 0; i < ends.size(); ++i) ends[i]->group = sets.find(int(i));
}

Eigen::Vector3d end_point(const Context& c, const VEnd& e) { return point(c.mesh, e.at >= 0 ? e.at : e.vertex); }

Eigen::Vector3d midpoint(const Context& c, int e) {
    return (point(c.mesh, c.topo.edges(e, 0)) + point(c.mesh, c.topo.edges(e, 1))) / 2;
}

bool is_junk(const Context& c, const VChain& ch, double h) {
    const VEnd &a = ch.ends[0], &b = ch.ends[1];
    if (ch.closed || a.type != b.type || a.group != b.group || a.type == EndType::Dead) return false;
    if (ch.edges.size() <= 2) return true;
    for (int e : ch.edges)
        if ((midpoint(c, e) - end_point(c, a)).norm() > h) return false;
    return true;
}

// Area-weighted outward normals of the boundary at every vertex (zero off the boundary).
Axes vertex_normals(const TetMesh& mesh) {
    Axes n = Axes::Zero(mesh.num_vertices(), 3);
    for (int f = 0; f < mesh.boundary_faces.rows(); ++f) {
        const Eigen::Vector3d p0 = point(mesh, mesh.boundary_faces(f, 0));
        const Eigen::Vector3d a = (point(mesh, mesh.boundary_faces(f, 1)) - p0).cross(point(mesh, mesh.boundary_faces(f, 2)) - p0);
        for (int k = 0; k < 3; ++k) n.row(mesh.boundary_faces(f, k)) += a.transpose();
    }
    return n;
}

// Junction nodes: placed at their vertices' mean, with the tets around them and their complex edges.
void finish_junctions(const Context& c, const std::vector<int>& cluster_node, ChainGraph& g) {
    std::vector<Eigen::Vector3d> sum(cluster_node.size(), Eigen::Vector3d::Zero());
    std::vector<int> count(cluster_node.size(), 0);
    for (int v = 0; v < c.mesh.num_vertices(); ++v) {
        const int cl = c.cluster[size_t(v)];
        if (cl < 0 || cluster_node[size_t(cl)] < 0) continue;
        sum[size_t(cl)] += point(c.mesh, v);
        count[size_t(cl)] += 1;
        ChainNode& n = g.nodes[size_t(cluster_node[size_t(cl)])];
        for (int k = c.topo.vert_tets_start[size_t(v)]; k < c.topo.vert_tets_start[size_t(v) + 1]; ++k)
            n.tets.push_back(c.topo.vert_tets[size_t(k)]);
    }
    for (int e = 0; e < int(c.val.size()); ++e) {
        const int cl = c.cluster[size_t(c.topo.edges(e, 0))];
        if (c.val[size_t(e)] == -1 && cl >= 0 && cluster_node[size_t(cl)] >= 0)
            g.nodes[size_t(cluster_node[size_t(cl)])].n_complex += 1;
    }
    for (size_t cl = 0; cl < cluster_node.size(); ++cl) {
        if (cluster_node[cl] < 0) continue;
        ChainNode& n = g.nodes[size_t(cluster_node[cl])];
        n.position = sum[cl] / double(count[cl]);
        std::sort(n.tets.begin(), n.tets.end());
        n.tets.erase(std::unique(n.tets.begin(), n.tets.end()), n.tets.end());
    }
    for (ChainNode& n : g.nodes) {
        std::sort(n.verts.begin(), n.verts.end());
        n.verts.erase(std::unique(n.verts.begin(), n.verts.end()), n.verts.end());
    }
}

void assemble(const Context& c, const std::vector<VChain>& chains, const Axes& axis, ChainGraph& g) {
    std::map<std::pair<int, int>, int> node_of;
    std::vector<Eigen::Vector3d> sum;
    const Axes normal = vertex_normals(c.mesh);
    std::vector<int> cluster_node(size_t(c.nclusters), -1);
    auto node = [&](const VEnd& e) {
        auto [it, inserted] = node_of.emplace(std::make_pair(int(e.type), e.group), int(g.nodes.size()));
        if (inserted) {
            g.nodes.emplace_back();
            g.nodes.back().boundary = e.type == EndType::Boundary;
            sum.push_back(Eigen::Vector3d::Zero());
        }
        ChainNode& n = g.nodes[size_t(it->second)];
        sum[size_t(it->second)] += end_point(c, e);
        if (n.boundary) {
            n.verts.push_back(e.at);
            const Eigen::Vector3d nn = normal.row(e.at).transpose().normalized();
            n.axes_normal = n.axes_normal && std::abs(axis.row(e.edge).dot(nn.transpose())) >= kCos45;
        }
        if (e.type == EndType::Junction) cluster_node[size_t(e.group)] = it->second;
        return it->second;
    };
    for (const VChain& ch : chains) {
        if (is_junk(c, ch, g.h_mean)) {
            ++g.junk_chains;
            continue;
        }
        ChainCurve cc;
        cc.faces = ch.edges;
        cc.closed = ch.closed;
        if (!ch.closed)
            for (int k = 0; k < 2; ++k) cc.ends[k] = node(ch.ends[k]);
        g.curves.push_back(std::move(cc));
    }
    std::vector<int> count(g.nodes.size(), 0);
    for (const ChainCurve& cc : g.curves)
        if (!cc.closed) count[size_t(cc.ends[0])] += 1, count[size_t(cc.ends[1])] += 1;
    for (size_t i = 0; i < g.nodes.size(); ++i) g.nodes[i].position = sum[i] / std::max(count[i], 1);
    finish_junctions(c, cluster_node, g);
    for (ChainCurve& cc : g.curves) {
        if (!cc.closed) cc.points.push_back(g.nodes[size_t(cc.ends[0])].position);
        for (int e : cc.faces) {
            cc.face_point.push_back(int(cc.points.size()));
            cc.points.push_back(midpoint(c, e));
        }
        if (!cc.closed) cc.points.push_back(g.nodes[size_t(cc.ends[1])].position);
    }
}

}  // namespace

ChainGraph trace_edge_chains(const TetMesh& mesh, const TetTopology& topo, const std::vector<int>& edge_valence,
                             const Axes& edge_axis, const ChainOptions& options) {
    if (edge_valence.size() != size_t(topo.edges.rows()) || edge_axis.rows() != topo.edges.rows())
        throw Error("singularities", "edge labels have " + std::to_string(edge_valence.size()) + " entries for " +
                                         std::to_string(topo.edges.rows()) + " topology edges");
    const Context c = classify_vertices(mesh, topo, edge_valence);
    std::vector<VChain> chains = walk_chains(c);
    ChainGraph graph;
    graph.h_mean = mean_edge_length(mesh, topo);
    resolve_dead_ends(c, options.attach_distance * graph.h_mean, chains, graph);
    group_boundary_ends(c, chains);
    assemble(c, chains, edge_axis, graph);
    graph.joined = detail::join_and_drop_loops(graph, mesh);
    detail::renumber(graph);
    return graph;
}

}  // namespace framefix
