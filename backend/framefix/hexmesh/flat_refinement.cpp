#include "framefix/hexmesh/flat_refinement.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "framefix/hexmesh/hex_projection.h"

namespace framefix {

namespace {

// Share of an edge's length over which its leaving direction is read at most: further on, a
// curved edge (the notch's arc) turns away from its tangent.
constexpr double kMaxReachShare = 0.4;
// Points of a straight new edge's polyline: enough for the hex grid's resampling, which only
// interpolates along it.
constexpr int kStraightEdgePoints = 9;

Eigen::Vector3d row(const Points& p, Eigen::Index i) { return p.row(i).transpose(); }

double length(const Points& p) {
    double l = 0;
    for (Eigen::Index i = 1; i < p.rows(); ++i) l += (p.row(i) - p.row(i - 1)).norm();
    return l;
}

// The point at arc-length share `f` of a polyline, and the index of the polyline point nearest it.
Eigen::Vector3d point_at(const Points& p, double f, Eigen::Index* nearest = nullptr) {
    const double target = f * length(p);
    double s = 0;
    for (Eigen::Index i = 1; i < p.rows(); ++i) {
        const double step = (p.row(i) - p.row(i - 1)).norm();
        if (s + step >= target && step > 0) {
            const double g = (target - s) / step;
            if (nearest) *nearest = g < 0.5 ? i - 1 : i;
            return (1 - g) * row(p, i - 1) + g * row(p, i);
        }
        s += step;
    }
    if (nearest) *nearest = p.rows() - 1;
    return row(p, p.rows() - 1);
}

// Unit direction in which edge `e` leaves `corner`.
Eigen::Vector3d leaving(const ComplexEdge& e, int corner, double reach) {
    const Points& p = e.polyline;
    const bool forward = e.a == corner;
    const Eigen::Index n = p.rows(), start = forward ? 0 : n - 1, step = forward ? 1 : -1;
    const double target = std::min(reach, kMaxReachShare * length(p));
    double s = 0;
    for (Eigen::Index i = start + step; i >= 0 && i < n; i += step) {
        s += (p.row(i) - p.row(i - step)).norm();
        if (s >= target) return (row(p, i) - row(p, start)).normalized();
    }
    return (row(p, n - 1 - start) - row(p, start)).normalized();
}

// Local edge along `axis` through local corner `l`.
int edge_at(int l, int axis) {
    const int bits[3] = {l & 1, (l >> 1) & 1, (l >> 2) & 1};
    const int lo = std::min((axis + 1) % 3, (axis + 2) % 3), hi = std::max((axis + 1) % 3, (axis + 2) % 3);
    return 4 * axis + bits[lo] + 2 * bits[hi];
}

struct FlatTest {
    const BlockComplex& cx;
    double reach;
    double cos_flat, cos_end;  // an edge is flat when one end passes cos_flat and the other cos_end
    // The block's edges along axes a1 and a2 leave local corner l more than acos(cos) apart.
    bool apart(const ComplexBlock& b, int l, int a1, int a2, double cos) const {
        const int c = b.corners[l];
        return leaving(cx.edges[b.edges[edge_at(l, a1)]], c, reach).dot(leaving(cx.edges[b.edges[edge_at(l, a2)]], c, reach)) < cos;
    }
    bool flat_edge(const ComplexBlock& b, int e) const {
        const int d = e / 4, d1 = (d + 1) % 3, d2 = (d + 2) % 3;
        const auto l = edge_local_corners(e);
        return (apart(b, l[0], d1, d2, cos_flat) && apart(b, l[1], d1, d2, cos_end)) ||
               (apart(b, l[1], d1, d2, cos_flat) && apart(b, l[0], d1, d2, cos_end));
    }
    // Sum over the edge's two ends of the cosines between the two other edges (lower: flatter).
    double flatness(const ComplexBlock& b, int e) const {
        const int d = e / 4, d1 = (d + 1) % 3, d2 = (d + 2) % 3;
        double sum = 0;
        for (int l : edge_local_corners(e)) {
            const int c = b.corners[l];
            sum += leaving(cx.edges[b.edges[edge_at(l, d1)]], c, reach).dot(leaving(cx.edges[b.edges[edge_at(l, d2)]], c, reach));
        }
        return sum;
    }
    bool flat_corner(const ComplexBlock& b, int l) const {
        return apart(b, l, 0, 1, cos_flat) || apart(b, l, 1, 2, cos_flat) || apart(b, l, 0, 2, cos_flat);
    }
};

double cos_of(double flat_deg) { return std::cos((180.0 - flat_deg) * M_PI / 180.0); }

FlatTest flat_test(const BlockComplex& cx, double reach, double flat_deg, double end_deg) {
    return {cx, reach, cos_of(flat_deg), cos_of(end_deg)};
}

Points polyline_of(const std::vector<Eigen::Vector3d>& pts) {
    Points out(Eigen::Index(pts.size()), 3);
    for (size_t i = 0; i < pts.size(); ++i) out.row(Eigen::Index(i)) = pts[i].transpose();
    return out;
}

// Weiszfeld's iteration for the point with the least sum of distances to three points, from
// their centroid; the centroid when the minimum nears a vertex (a triangle angle of 120 degrees
// or more), which would make a degenerate spoke.
Eigen::Vector3d fermat_point(const std::array<Eigen::Vector3d, 3>& p) {
    constexpr int kIterations = 50;
    constexpr double kMinSpokeShare = 0.2;  // of the mean distance from the centroid
    const Eigen::Vector3d centroid = (p[0] + p[1] + p[2]) / 3;
    double mean = 0;
    for (const auto& q : p) mean += (q - centroid).norm() / 3;
    Eigen::Vector3d x = centroid;
    for (int it = 0; it < kIterations; ++it) {
        Eigen::Vector3d num = Eigen::Vector3d::Zero();
        double den = 0;
        for (const auto& q : p) {
            const double d = (q - x).norm();
            if (d < kMinSpokeShare * mean) return centroid;
            num += q / d, den += 1 / d;
        }
        x = num / den;
    }
    for (const auto& q : p)
        if ((q - x).norm() < kMinSpokeShare * mean) return centroid;
    return x;
}

// The vertex of a face's triangles nearest p.
int nearest_vertex(const TetMesh& mesh, const ComplexFace& f, const Eigen::Vector3d& p) {
    int best = -1;
    for (const Eigen::Vector3i& t : f.triangles)
        for (int v : {t[0], t[1], t[2]})
            if (best < 0 || (mesh.points.row(v).transpose() - p).norm() < (mesh.points.row(best).transpose() - p).norm()) best = v;
    return best;
}

// Builds the three blocks of one refined block; keeps the complex's lookup tables current.
class Splitter {
public:
    Splitter(const TetMesh& mesh, BlockComplex& cx) : mesh_(mesh), cx_(cx) {
        for (int e = 0; e < int(cx.edges.size()); ++e) edge_of_[{cx.edges[e].a, cx.edges[e].b}] = e;
        for (int f = 0; f < int(cx.faces.size()); ++f) face_of_[sorted(cx.faces[f].corners)] = f;
    }

    // Refines block `bi` along its flat local edge `e`, or returns why it cannot.
    std::string refine(int bi, int e, const std::vector<int>& edge_users);

private:
    const TetMesh& mesh_;
    BlockComplex& cx_;
    std::optional<SurfaceLocator> locator_;  // made on the first refined block
    std::map<std::pair<int, int>, int> edge_of_;
    std::map<std::array<int, 4>, int> face_of_;

    static std::array<int, 4> sorted(std::array<int, 4> c) { return std::sort(c.begin(), c.end()), c; }
    int edge(int x, int y) const { return edge_of_.at(std::minmax(x, y)); }

    int add_corner(const Eigen::Vector3d& p, std::vector<int> vertices) {
        std::sort(vertices.begin(), vertices.end());
        cx_.corners.push_back({p, vertices});
        return int(cx_.corners.size()) - 1;
    }
    // Edge from corner x to y through `pts` (x's and y's positions included) and mesh vertices `chain`.
    void add_edge(int x, int y, std::vector<Eigen::Vector3d> pts, std::vector<int> chain) {
        if (x > y) std::reverse(pts.begin(), pts.end()), std::reverse(chain.begin(), chain.end()), std::swap(x, y);
        ComplexEdge e;
        e.a = x, e.b = y, e.polyline = polyline_of(pts), e.chain = std::move(chain);
        edge_of_[{x, y}] = int(cx_.edges.size());
        cx_.edges.push_back(std::move(e));
    }
    void add_straight_edge(int x, int y) {
        std::vector<Eigen::Vector3d> pts;
        for (int i = 0; i < kStraightEdgePoints; ++i) {
            const double f = double(i) / (kStraightEdgePoints - 1);
            pts.push_back((1 - f) * cx_.corners[x].position + f * cx_.corners[y].position);
        }
        add_edge(x, y, pts, {});
    }
    void add_face(std::array<int, 4> corners, const ComplexFace* parent) {
        face_of_[sorted(corners)] = int(cx_.faces.size());
        cx_.faces.push_back({corners, parent ? parent->triangles : std::vector<Eigen::Vector3i>{}, parent && parent->boundary});
    }
    // Splits the edge from x to y at its middle chain vertex: the new corner.
    int split_edge(int x, int y);
    // A cube over 8 corners (local order), its edges and faces looked up by their corners.
    ComplexBlock cube(int id, const std::array<int, 8>& corners) const {
        ComplexBlock b;
        b.id = id, b.corners = corners;
        for (int e = 0; e < 12; ++e) {
            const auto l = edge_local_corners(e);
            b.edges[e] = edge(corners[l[0]], corners[l[1]]);
        }
        for (int f = 0; f < 6; ++f) {
            const auto l = face_local_corners(f);
            b.faces[f] = face_of_.at(sorted({corners[l[0]], corners[l[1]], corners[l[2]], corners[l[3]]}));
        }
        return b;
    }
};

int Splitter::split_edge(int x, int y) {
    const ComplexEdge old = cx_.edges[edge(x, y)];
    std::vector<Eigen::Vector3d> pts;
    for (Eigen::Index i = 0; i < old.polyline.rows(); ++i) pts.push_back(row(old.polyline, i));
    std::vector<int> chain = old.chain;
    if (old.a != x) std::reverse(pts.begin(), pts.end()), std::reverse(chain.begin(), chain.end());
    Eigen::Index at = 0;
    const Eigen::Vector3d mid = point_at(polyline_of(pts), 0.5, &at);
    if (pts.size() <= 2) pts.insert(pts.begin() + 1, mid), at = 1;
    at = std::clamp<Eigen::Index>(at, 1, Eigen::Index(pts.size()) - 2);
    // The chain vertex under the new corner (the polyline's inner points are chain vertices).
    int vertex = -1;
    for (int v : chain)
        if (vertex < 0 || (mesh_.points.row(v).transpose() - pts[size_t(at)]).norm() <
                              (mesh_.points.row(vertex).transpose() - pts[size_t(at)]).norm())
            vertex = v;
    const int c = add_corner(pts[size_t(at)], vertex >= 0 ? std::vector<int>{vertex} : std::vector<int>{});
    const auto cut = vertex >= 0 ? std::find(chain.begin(), chain.end(), vertex) : chain.begin();
    std::vector<Eigen::Vector3d> first(pts.begin(), pts.begin() + at + 1), second(pts.begin() + at, pts.end());
    add_edge(x, c, first, std::vector<int>(chain.begin(), std::min(cut + 1, chain.end())));
    add_edge(c, y, second, std::vector<int>(cut, chain.end()));
    return c;
}

std::string Splitter::refine(int bi, int e, const std::vector<int>& edge_users) {
    const ComplexBlock old = cx_.blocks[size_t(bi)];
    // Frame (x, y, z): z along the flat edge, which sits at x = y = 0; right-handed like the block.
    const int d = e / 4, l0 = edge_local_corners(e)[0];
    std::array<int, 3> axis{(d + 1) % 3, (d + 2) % 3, d}, flip{(l0 >> ((d + 1) % 3)) & 1, (l0 >> ((d + 2) % 3)) & 1, 0};
    if ((flip[0] + flip[1]) % 2) std::swap(axis[0], axis[1]), std::swap(flip[0], flip[1]);
    auto at = [&](int x, int y, int z) {
        int bits[3];
        bits[axis[0]] = x ^ flip[0], bits[axis[1]] = y ^ flip[1], bits[axis[2]] = z;
        return old.corners[local_corner(bits[0], bits[1], bits[2])];
    };
    auto face = [&](int n, int side) { return old.faces[2 * axis[n] + (side ^ flip[n])]; };
    for (auto [n, side] : {std::pair{0, 1}, {1, 1}, {2, 0}, {2, 1}})
        if (!cx_.faces[face(n, side)].boundary) return "its face opposite the flat edge or at its ends is shared with another block";
    for (int z = 0; z < 2; ++z)
        if (edge_users[edge(at(1, 0, z), at(1, 1, z))] > 1 || edge_users[edge(at(0, 1, z), at(1, 1, z))] > 1)
            return "an edge to split is shared with another block";

    // Per end z: B on the flat edge, A and C its neighbours, D opposite; new corners mAD, mCD, O.
    std::array<int, 2> B, A, C, D, mAD, mCD, O;
    const ComplexFace x1 = cx_.faces[face(0, 1)], y1 = cx_.faces[face(1, 1)];
    for (int z = 0; z < 2; ++z) {
        B[z] = at(0, 0, z), A[z] = at(1, 0, z), C[z] = at(0, 1, z), D[z] = at(1, 1, z);
        mAD[z] = split_edge(A[z], D[z]);
        mCD[z] = split_edge(C[z], D[z]);
        // O at the Fermat point of its three spokes' far ends, onto the end face: the three
        // angles at O are 120 degrees (the Coons middle of the face left one near 145 on the notch).
        const ComplexFace end = cx_.faces[face(2, z)];
        const Eigen::Vector3d centre =
            fermat_point({cx_.corners[B[z]].position, cx_.corners[mAD[z]].position, cx_.corners[mCD[z]].position});
        if (!locator_) locator_.emplace(mesh_);
        const Eigen::Vector3d o = FaceProjector(mesh_, end, *locator_).project(centre, {});
        const int vertex = nearest_vertex(mesh_, end, o);
        O[z] = add_corner(o, vertex >= 0 ? std::vector<int>{vertex} : std::vector<int>{});
        for (int c : {B[z], mAD[z], mCD[z]}) add_straight_edge(O[z], c);
        add_face({B[z], A[z], mAD[z], O[z]}, &end);
        add_face({B[z], O[z], mCD[z], C[z]}, &end);
        add_face({O[z], mAD[z], D[z], mCD[z]}, &end);
    }
    for (auto* m : {&mAD, &mCD, &O}) add_straight_edge((*m)[0], (*m)[1]);
    add_face({A[0], mAD[0], mAD[1], A[1]}, &x1);
    add_face({mAD[0], D[0], D[1], mAD[1]}, &x1);
    add_face({C[0], mCD[0], mCD[1], C[1]}, &y1);
    add_face({mCD[0], D[0], D[1], mCD[1]}, &y1);
    add_face({B[0], O[0], O[1], B[1]}, nullptr);
    add_face({O[0], mAD[0], mAD[1], O[1]}, nullptr);
    add_face({O[0], mCD[0], mCD[1], O[1]}, nullptr);
    // The three quads (x, y) of the cross-section, counter-clockwise like the block's frame.
    const std::array<std::array<std::array<int, 2>, 4>, 3> quads{{{B, A, mAD, O}, {B, O, mCD, C}, {O, mAD, D, mCD}}};
    const int next_id = int(cx_.blocks.size());
    for (size_t q = 0; q < 3; ++q) {
        std::array<int, 8> corners{};
        const int order[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int n = 0; n < 4; ++n)
            for (int z = 0; z < 2; ++z) corners[size_t(local_corner(order[n][0], order[n][1], z))] = quads[q][size_t(n)][size_t(z)];
        const ComplexBlock b = cube(q == 0 ? old.id : next_id + int(q) - 1, corners);
        if (q == 0) cx_.blocks[size_t(bi)] = b;
        else cx_.blocks.push_back(b);
    }
    return "";
}

// Drops the edges and faces no block uses any more, and renumbers the rest.
void compact(BlockComplex& cx) {
    std::vector<int> edge_id(cx.edges.size(), -1), face_id(cx.faces.size(), -1);
    for (const ComplexBlock& b : cx.blocks) {
        for (int e : b.edges) edge_id[size_t(e)] = 0;
        for (int f : b.faces) face_id[size_t(f)] = 0;
    }
    std::vector<ComplexEdge> edges;
    std::vector<ComplexFace> faces;
    for (size_t e = 0; e < cx.edges.size(); ++e)
        if (edge_id[e] == 0) edge_id[e] = int(edges.size()), edges.push_back(std::move(cx.edges[e]));
    for (size_t f = 0; f < cx.faces.size(); ++f)
        if (face_id[f] == 0) face_id[f] = int(faces.size()), faces.push_back(std::move(cx.faces[f]));
    for (ComplexBlock& b : cx.blocks) {
        for (int& e : b.edges) e = edge_id[size_t(e)];
        for (int& f : b.faces) f = face_id[size_t(f)];
    }
    cx.edges = std::move(edges), cx.faces = std::move(faces);
}

}  // namespace

FlatCount count_flat(const BlockComplex& cx, double reach, double flat_deg) {
    const FlatTest test = flat_test(cx, reach, flat_deg, flat_deg);
    FlatCount n;
    for (const ComplexBlock& b : cx.blocks) {
        for (int e = 0; e < 12; ++e) n.edges += test.flat_edge(b, e);
        for (int l = 0; l < 8; ++l)
            if (test.flat_corner(b, l)) n.corners += 1, n.where.push_back(cx.corners[b.corners[l]].position);
    }
    return n;
}

FlatRefinement refine_flat_edges(const TetMesh& mesh, double reach, double flat_deg, double end_deg, BlockComplex& cx) {
    FlatRefinement out;
    out.before = count_flat(cx, reach, flat_deg);
    out.blocks_before = int(cx.blocks.size());
    std::vector<int> edge_users(cx.edges.size(), 0);
    for (const ComplexBlock& b : cx.blocks)
        for (int e : b.edges) edge_users[size_t(e)] += 1;
    Splitter split(mesh, cx);
    const int original = int(cx.blocks.size());
    for (int bi = 0; bi < original; ++bi) {
        const FlatTest test = flat_test(cx, reach, flat_deg, end_deg);
        const ComplexBlock& b = cx.blocks[size_t(bi)];
        std::vector<std::pair<double, int>> flat;  // candidates, flattest first
        for (int e = 0; e < 12; ++e)
            if (test.flat_edge(b, e)) flat.push_back({test.flatness(b, e), e});
        if (flat.empty()) continue;
        std::sort(flat.begin(), flat.end());
        const std::string block = "block " + std::to_string(b.id);
        std::string why;
        for (const auto& [score, e] : flat)
            if ((why = split.refine(bi, e, edge_users)).empty()) break;
        if (why.empty()) out.refined += 1;
        else out.skipped.push_back(block + ": " + why);
    }
    compact(cx);
    out.after = count_flat(cx, reach, flat_deg);
    out.blocks_after = int(cx.blocks.size());
    return out;
}

}  // namespace framefix
