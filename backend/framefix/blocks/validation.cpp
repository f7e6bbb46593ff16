#include "framefix/blocks/validation.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "framefix/core/disjoint_set.h"
#include "framefix/mesh/keys.h"

namespace framefix {

namespace {

struct Adjacency {                 // triangle pairs sharing a mesh edge (non-manifold edges: all pairs)
    struct Pair { int a, b; double length; int v0, v1; };
    std::vector<Pair> pairs;
    bool manifold = true;
    int edges = 0, verts = 0;
};

Adjacency adjacency(const TetMesh& mesh, const std::vector<BoundaryTriangle>& S) {
    Adjacency adj;
    const std::uint64_t nv = mesh.num_vertices();
    // Iterated below: the pair order (hence sums over pairs) follows these key values.
    std::unordered_map<PairKey, std::vector<int>> by_edge;
    std::set<int> verts;
    for (int i = 0; i < int(S.size()); ++i)
        for (int k = 0; k < 3; ++k) {
            const int a = S[i].verts[k], c = S[i].verts[(k + 1) % 3];
            by_edge[edge_key(a, c, nv)].push_back(i);
            verts.insert(a);
        }
    for (auto& [key, tris] : by_edge) {
        adj.manifold &= tris.size() == 2;
        const auto [v0, v1] = key_ids(key, nv);
        const double len = (mesh.points.row(v0) - mesh.points.row(v1)).norm();
        for (size_t x = 0; x < tris.size(); ++x)
            for (size_t y = x + 1; y < tris.size(); ++y) adj.pairs.push_back({tris[x], tris[y], len, v0, v1});
    }
    adj.edges = int(by_edge.size()), adj.verts = int(verts.size());
    return adj;
}

int renumber(std::vector<int>& patch) {
    std::unordered_map<int, int> id;
    for (int& p : patch) p = id.try_emplace(p, int(id.size())).first->second;
    return int(id.size());
}

std::vector<int> components(int n, const Adjacency& adj, const std::vector<int>& label) {
    DisjointSet sets(n);
    for (const auto& p : adj.pairs)
        if (label[p.a] == label[p.b]) sets.merge_into(p.a, p.b);
    std::vector<int> out(n);
    for (int i = 0; i < n; ++i) out[i] = sets.find(i);
    renumber(out);
    return out;
}

double angle_deg(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    if (a.norm() == 0 || b.norm() == 0) return 180;
    return std::acos(std::clamp(a.dot(b) / (a.norm() * b.norm()), -1.0, 1.0)) * 180 / M_PI;
}

struct PatchStats { std::vector<double> area, perimeter; std::vector<std::map<int, double>> contact; };

PatchStats patch_stats(const std::vector<BoundaryTriangle>& S, const Adjacency& adj, const std::vector<int>& patch, int n) {
    PatchStats s{std::vector<double>(n, 0), std::vector<double>(n, 0), std::vector<std::map<int, double>>(n)};
    for (size_t i = 0; i < S.size(); ++i) s.area[patch[i]] += 0.5 * S[i].normal.norm();
    for (const auto& p : adj.pairs) {
        const int a = patch[p.a], b = patch[p.b];
        if (a == b) continue;
        s.perimeter[a] += p.length, s.perimeter[b] += p.length;
        s.contact[a][b] += p.length, s.contact[b][a] += p.length;
    }
    return s;
}

int longest_contact(const std::map<int, double>& contact) {
    int best = -1;
    double most = -1;
    for (auto [q, l] : contact) if (l > most) most = l, best = q;
    return best;
}

// Merges per cleaning rule, one per round. A dome's block collects dozens of staircase scraps
// along its rim; 30 rounds left one of them as a seventh face on half_sphere_box.
constexpr int kCleanRounds = 200;

// docs/algorithms.md#block-faces-and-patch-cleaning: tiny patches, thin staircase strips, and bevel strips between two ~90 deg flanks.
void clean_patches(const TetMesh& mesh, const std::vector<BoundaryTriangle>& S, const Adjacency& adj, double h,
                   const BlockOptions& o, std::vector<int>& patch) {
    for (int it = 0; it < kCleanRounds; ++it) {  // tiny patches, smallest first
        const int n = renumber(patch);
        const PatchStats s = patch_stats(S, adj, patch, n);
        int small = -1;
        for (int p = 0; p < n; ++p) {
            // A face of a hexahedron has 4 neighbouring faces: a small patch with <= 3 is a sliver
            // where 4 blocks meet along a line (two sheets crossing), not a face.
            const double limit = (s.contact[p].size() <= 3 ? o.sliver_area : o.patch_merge_area) * h * h;
            if (s.area[p] < limit && !s.contact[p].empty() && (small < 0 || s.area[p] < s.area[small])) small = p;
        }
        if (small < 0) break;
        const int target = longest_contact(s.contact[small]);
        for (int& p : patch) if (p == small) p = target;
    }
    for (int it = 0; it < kCleanRounds && o.thin_width > 0; ++it) {  // strips one tet wide
        const int n = renumber(patch);
        const PatchStats s = patch_stats(S, adj, patch, n);
        int thin = -1;
        double wmin = o.thin_width * h;
        for (int p = 0; p < n; ++p) {
            if (s.perimeter[p] <= 0) continue;
            const double w = 2 * s.area[p] / s.perimeter[p];
            if (w < wmin) wmin = w, thin = p;
        }
        if (thin < 0) break;
        const int target = longest_contact(s.contact[thin]);
        for (int& p : patch) if (p == thin) p = target;
    }
    for (int it = 0; it < 30 && o.bevel_width > 0; ++it) {
        const int n = renumber(patch);
        const PatchStats s = patch_stats(S, adj, patch, n);
        std::vector<Eigen::Vector3d> normal(n, Eigen::Vector3d::Zero());
        for (size_t i = 0; i < S.size(); ++i) normal[patch[i]] += S[i].normal;
        std::vector<int> order(n);
        std::iota(order.begin(), order.end(), 0);
        auto width = [&](int p) { return s.perimeter[p] > 0 ? 2 * s.area[p] / s.perimeter[p] : 1e300; };
        std::sort(order.begin(), order.end(), [&](int a, int b) { return width(a) < width(b); });
        bool split = false;
        for (int p : order) {
            if (width(p) >= o.bevel_width * h) break;
            std::vector<std::pair<double, int>> flank;
            for (auto [q, l] : s.contact[p]) flank.push_back({l, q});
            std::sort(flank.rbegin(), flank.rend());
            if (flank.size() < 2 || flank[1].first < 0.25 * s.perimeter[p]) continue;
            const int Q = flank[0].second, R = flank[1].second;
            const double qr = angle_deg(normal[Q], normal[R]);
            if (qr < 45 || qr > 135) continue;
            if (angle_deg(normal[p], normal[Q]) > 65 || angle_deg(normal[p], normal[R]) > 65) continue;
            auto centroid = [&](int i) {
                return Eigen::Vector3d((mesh.points.row(S[i].verts[0]) + mesh.points.row(S[i].verts[1]) +
                                        mesh.points.row(S[i].verts[2])).transpose() / 3);
            };
            std::vector<int> in_p, in_q, in_r;
            for (int i = 0; i < int(S.size()); ++i) {
                if (patch[i] == p) in_p.push_back(i);
                else if (patch[i] == Q) in_q.push_back(i);
                else if (patch[i] == R) in_r.push_back(i);
            }
            auto nearest = [&](const Eigen::Vector3d& c, const std::vector<int>& set) {
                double d = 1e300;
                for (int j : set) d = std::min(d, (centroid(j) - c).squaredNorm());
                return d;
            };
            std::vector<int> next = patch;
            for (int i : in_p) {
                const Eigen::Vector3d c = centroid(i);
                next[i] = nearest(c, in_q) <= nearest(c, in_r) ? Q : R;
            }
            patch = next;
            split = true;
            break;
        }
        if (!split) break;
    }
    renumber(patch);
}

// Per patch: the label most of its triangles carry.
std::vector<int> majority_labels(const std::vector<BoundaryTriangle>& S, const std::vector<int>& patch, int n) {
    std::vector<std::map<int, int>> votes(n);
    for (size_t i = 0; i < S.size(); ++i) votes[patch[i]][S[i].label] += 1;
    std::vector<int> out(n, 0);
    for (int p = 0; p < n; ++p) {
        int most = 0;
        for (auto [l, c] : votes[p]) if (c > most) most = c, out[p] = l;
    }
    return out;
}

// Patches whose majority label is in `dissolve` (neighbours that saw the contact as a sliver)
// merge into the patch they share the longest boundary with.
void dissolve_patches(const std::vector<BoundaryTriangle>& S, const Adjacency& adj, const std::vector<int>& dissolve,
                      std::vector<int>& patch) {
    for (int it = 0; it < kCleanRounds && !dissolve.empty(); ++it) {
        const int n = renumber(patch);
        const PatchStats s = patch_stats(S, adj, patch, n);
        const std::vector<int> label = majority_labels(S, patch, n);
        int gone = -1;
        for (int p = 0; p < n && gone < 0; ++p)
            if (!s.contact[p].empty() && std::find(dissolve.begin(), dissolve.end(), label[p]) != dissolve.end()) gone = p;
        if (gone < 0) break;
        const int target = longest_contact(s.contact[gone]);
        for (int& p : patch) if (p == gone) p = target;
    }
    renumber(patch);
}

// Vertices in >= 3 patches joined by mesh edges, as connected components: the staircase makes a
// corner a few vertices. A component of vertices in exactly 3 patches each, but more than 3 in
// all, is two corners one mesh edge apart, and splits by patch set (the sphere's radial block
// edges at the default size are 1.6 h long). Components with a vertex in 4 or more patches (a
// T-junction, four blocks along a line) stay whole.
std::vector<std::vector<int>> corner_clusters(const std::map<int, std::set<int>>& vp, const Adjacency& adj) {
    std::unordered_set<int> in3;  // vertices in 3 or more patches
    for (const auto& [v, ps] : vp)
        if (ps.size() >= 3) in3.insert(v);
    auto components = [&](auto&& joined) {
        std::unordered_map<int, std::vector<int>> cadj;
        for (const auto& p : adj.pairs)
            if (in3.count(p.v0) && in3.count(p.v1) && joined(p.v0, p.v1))
                cadj[p.v0].push_back(p.v1), cadj[p.v1].push_back(p.v0);
        std::unordered_map<int, int> of;  // corner vertex -> component
        std::vector<std::vector<int>> out;
        for (const auto& [v, ps] : vp) {
            if (ps.size() < 3 || of.count(v)) continue;
            out.push_back({});
            std::vector<int> stack{v};
            of[v] = int(out.size()) - 1;
            while (!stack.empty()) {
                const int x = stack.back();
                stack.pop_back();
                out.back().push_back(x);
                for (int y : cadj[x]) if (!of.count(y)) of[y] = of[v], stack.push_back(y);
            }
        }
        return std::pair{out, of};
    };
    const auto [whole, of] = components([](int, int) { return true; });
    std::vector<char> splits(whole.size(), 0);
    for (size_t c = 0; c < whole.size(); ++c) {
        std::set<int> all;
        bool pure = true;
        for (int v : whole[c]) all.insert(vp.at(v).begin(), vp.at(v).end()), pure &= vp.at(v).size() == 3;
        splits[c] = pure && all.size() > 3;
    }
    return components([&](int a, int b) { return !splits[of.at(a)] || vp.at(a) == vp.at(b); }).first;
}

}  // namespace

BlockFaces validate_block(const TetMesh& mesh, const std::vector<BoundaryTriangle>& S, double h,
                          const BlockOptions& o, BlockInfo& info, const std::vector<int>& dissolve) {
    BlockFaces out;
    const int nf = int(S.size());
    const Adjacency adj = adjacency(mesh, S);
    info.manifold = adj.manifold;
    info.euler = adj.verts - adj.edges + nf;
    std::vector<int> label(nf);
    for (int i = 0; i < nf; ++i) label[i] = S[i].label;
    std::vector<int> patch = components(nf, adj, label);
    clean_patches(mesh, S, adj, h, o, patch);
    dissolve_patches(S, adj, dissolve, patch);
    const int np = nf ? *std::max_element(patch.begin(), patch.end()) + 1 : 0;
    info.faces = np;

    // Disk test per patch: chi = V - E + F must be 1.
    bool disks = true;
    {
        std::vector<std::set<int>> pv(np);
        std::vector<std::set<std::pair<int, int>>> pe(np);
        std::vector<int> pf(np, 0);
        for (int i = 0; i < nf; ++i) {
            pf[patch[i]] += 1;
            for (int k = 0; k < 3; ++k) {
                const int a = S[i].verts[k], c = S[i].verts[(k + 1) % 3];
                pv[patch[i]].insert(a), pe[patch[i]].insert({std::min(a, c), std::max(a, c)});
            }
        }
        for (int p = 0; p < np; ++p) disks &= int(pv[p].size()) - int(pe[p].size()) + pf[p] == 1;
    }

    // Corners: vertices in >= 3 patches, clustered (corner_clusters).
    std::map<int, std::set<int>> vp;
    for (int i = 0; i < nf; ++i) for (int k = 0; k < 3; ++k) vp[S[i].verts[k]].insert(patch[i]);
    const std::vector<std::vector<int>> clusters = corner_clusters(vp, adj);
    info.corners = int(clusters.size());
    bool degree3 = true;
    std::vector<Eigen::Vector3d> corner_pos;
    std::vector<std::set<int>> corner_patches;
    for (const auto& c : clusters) {
        std::set<int> ps;
        Eigen::Vector3d pos = Eigen::Vector3d::Zero();
        for (int v : c) ps.insert(vp[v].begin(), vp[v].end()), pos += mesh.points.row(v).transpose();
        degree3 &= ps.size() == 3;
        corner_pos.push_back(pos / double(c.size()));
        corner_patches.push_back(ps);
    }

    // Edges: per patch pair, connected chains of the mesh edges between the two patches.
    std::map<std::pair<int, int>, std::vector<std::pair<int, int>>> chains;
    for (const auto& p : adj.pairs) {
        const int a = patch[p.a], b = patch[p.b];
        if (a != b) chains[{std::min(a, b), std::max(a, b)}].push_back({p.v0, p.v1});
    }
    info.edges = 0;
    std::vector<Eigen::Vector3d> centroid(nf);
    for (int i = 0; i < nf; ++i)
        centroid[i] = (mesh.points.row(S[i].verts[0]) + mesh.points.row(S[i].verts[1]) + mesh.points.row(S[i].verts[2])).transpose() / 3;
    std::vector<std::vector<int>> of_patch(np);
    for (int i = 0; i < nf; ++i) of_patch[patch[i]].push_back(i);
    auto mean_normal_near = [&](int p, const std::vector<Eigen::Vector3d>& at) {
        Eigen::Vector3d n = Eigen::Vector3d::Zero();
        for (int i : of_patch[p])
            for (const auto& x : at) if ((centroid[i] - x).squaredNorm() < 4 * h * h) { n += S[i].normal; break; }
        return n;
    };
    info.flat_edges = 0;
    for (const auto& [key, segs] : chains) {
        // Chains counted as connected components of the segments' vertices (ascending ids).
        std::vector<int> verts;
        for (auto [a, c] : segs) verts.push_back(a), verts.push_back(c);
        std::sort(verts.begin(), verts.end());
        verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
        auto local = [&](int v) { return int(std::lower_bound(verts.begin(), verts.end(), v) - verts.begin()); };
        DisjointSet sets(int(verts.size()));
        int chains_here = int(verts.size());
        for (auto [a, c] : segs) chains_here -= sets.unite(local(a), local(c));
        std::vector<Eigen::Vector3d> chain_pts;
        for (int v : verts) chain_pts.push_back(mesh.points.row(v).transpose());
        info.edges += chains_here;
        // Flat-edge proxy: outward mean normals of the two patches within 2 h of their chain.
        if (angle_deg(mean_normal_near(key.first, chain_pts), mean_normal_near(key.second, chain_pts)) < o.flat_deg)
            info.flat_edges += 1;
    }
    info.flat_corners = 0;
    for (size_t c = 0; c < clusters.size(); ++c) {
        std::vector<Eigen::Vector3d> n;
        for (int p : corner_patches[c]) n.push_back(mean_normal_near(p, {corner_pos[c]}));
        bool flat = false;
        for (size_t x = 0; x < n.size(); ++x)
            for (size_t y = x + 1; y < n.size(); ++y) flat |= angle_deg(n[x], n[y]) < o.flat_deg;
        info.flat_corners += flat;
    }

    // Patch labels (majority) and corners, for conformity.
    out.label = majority_labels(S, patch, np);
    out.corners.assign(np, {});
    {
        for (size_t c = 0; c < clusters.size(); ++c)
            for (int p : corner_patches[c]) out.corners[p].push_back(corner_pos[c]);
        out.cleaned.resize(nf);
        for (int i = 0; i < nf; ++i) out.cleaned[i] = out.label[patch[i]];
        out.patch = patch;
        out.corner_vertices = clusters;
        for (const auto& ps : corner_patches) out.corner_patches.emplace_back(ps.begin(), ps.end());
        out.corner_position = corner_pos;
    }

    // Counts and degrees alone admit a U-shaped face that wraps three sides of a box and two
    // 2-cornered faces (chamfer_top with a chamfer folded both ways); a hexahedron's faces are quads.
    int odd_face_corners = 4;
    info.face_corners_off = 0;
    for (const auto& c : out.corners) {
        if (c.size() != 4) odd_face_corners = int(c.size());
        info.face_corners_off += std::abs(int(c.size()) - 4);
    }
    const bool four_cornered = odd_face_corners == 4;
    const std::pair<bool, std::string> tests[] = {
        {info.manifold, "non-manifold boundary"},
        {info.euler == 2, "boundary euler " + std::to_string(info.euler)},
        {info.faces == 6, "faces " + std::to_string(info.faces)},
        {info.edges == 12, "edges " + std::to_string(info.edges)},
        {info.corners == 8, "corners " + std::to_string(info.corners)},
        {disks, "a face is not a disk"},
        {degree3, "a corner is not of degree 3"},
        {four_cornered, "a face has " + std::to_string(odd_face_corners) + " corners"},
    };
    info.valid = true, info.reason.clear();  // a block validated again (one-sided contacts) drops its old reason
    for (const auto& [ok, why] : tests)
        if (!ok) { info.valid = false, info.reason = why; break; }
    return out;
}

std::vector<std::vector<int>> one_sided_contacts(const std::vector<BlockFaces>& faces,
                                                 const std::vector<std::map<int, int>>& shared) {
    auto patches = [&](int b, int label) { return std::count(faces[b].label.begin(), faces[b].label.end(), label); };
    std::vector<std::vector<int>> out(faces.size());
    for (int a = 0; a < int(faces.size()); ++a)
        for (auto [b, n] : shared[a])
            if (patches(a, b) > 0 && patches(b, a) == 0) out[a].push_back(b);
    return out;
}

std::vector<BlockPair> check_conformity(const std::vector<BlockFaces>& faces, double tolerance) {
    std::vector<BlockPair> out;
    const int n = int(faces.size());
    for (int b = 0; b < n; ++b)
        for (int c = b + 1; c < n; ++c) {
            std::vector<int> pb, pc;
            for (int p = 0; p < int(faces[b].label.size()); ++p) if (faces[b].label[p] == c) pb.push_back(p);
            for (int p = 0; p < int(faces[c].label.size()); ++p) if (faces[c].label[p] == b) pc.push_back(p);
            if (pb.empty() && pc.empty()) continue;
            BlockPair pair{b, c, false, false, ""};  // one_face only once checked below
            if (pb.size() != 1 || pc.size() != 1) {
                pair.reason = "patches " + std::to_string(pb.size()) + "|" + std::to_string(pc.size());
            } else {
                const auto &Cb = faces[b].corners[pb[0]], &Cc = faces[c].corners[pc[0]];
                if (Cb.size() != 4 || Cc.size() != 4) {
                    pair.reason = "corners " + std::to_string(Cb.size()) + "|" + std::to_string(Cc.size());
                } else {
                    double worst = 0;
                    for (const auto* pair_sets : {&Cb, &Cc}) {
                        const auto& other = pair_sets == &Cb ? Cc : Cb;
                        for (const auto& x : *pair_sets) {
                            double d = 1e300;
                            for (const auto& y : other) d = std::min(d, (x - y).norm());
                            worst = std::max(worst, d);
                        }
                    }
                    pair.one_face = true;
                    pair.conforming = worst <= tolerance;
                    if (!pair.conforming) pair.reason = "corner mismatch " + std::to_string(worst);
                }
            }
            out.push_back(pair);
        }
    return out;
}

}  // namespace framefix
