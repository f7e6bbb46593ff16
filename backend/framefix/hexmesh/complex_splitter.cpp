// Editing a block complex: a block split in two by a sheet, a block with a flat edge split in
// three by the template (docs/algorithms.md#flat-edge-refinement).
#include "framefix/hexmesh/complex_splitter.h"

#include <algorithm>
#include <map>
#include <optional>

#include "framefix/hexmesh/hex_grid.h"
#include "framefix/hexmesh/hex_projection.h"

namespace framefix {

namespace {

// Points of a straight new edge's polyline: enough for the hex grid's resampling, which only
// interpolates along it.
constexpr int kStraightEdgePoints = 9;

Eigen::Vector3d row(const Points& p, Eigen::Index i) { return p.row(i).transpose(); }

// The point at arc-length share `f` of a polyline, and the index of the polyline point nearest it.
Eigen::Vector3d point_at(const Points& p, double f, Eigen::Index* nearest = nullptr) {
    const double target = f * polyline_length(p);
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

// A block's corners seen along a flat edge: index at(x, y, z), the edge at x = y = 0, z along it.
using Frame = std::array<int, 8>;
constexpr int at(int x, int y, int z) { return x + 2 * y + 4 * z; }

// Splits blocks of a complex (by the template, by sheets); keeps its lookup tables current.
class Splitter {
public:
    Splitter(const TetMesh& mesh, BlockComplex& cx) : mesh_(mesh), cx_(cx) {
        for (int e = 0; e < int(cx.edges.size()); ++e) edge_of_[{cx.edges[e].a, cx.edges[e].b}] = e;
        for (int f = 0; f < int(cx.faces.size()); ++f) face_of_[sorted(cx.faces[f].corners)] = f;
    }

    // Refines block `bi` along its flat local edge `e`, with the blocks the flat edge runs on
    // into face to face, or returns why it cannot.
    std::string refine(int bi, int e);

private:
    const TetMesh& mesh_;
    BlockComplex& cx_;
    std::optional<SurfaceLocator> locator_;  // made on the first refined block
    std::map<std::pair<int, int>, int> edge_of_;
    std::map<std::array<int, 4>, int> face_of_;
    std::map<std::pair<int, int>, int> middle_of_;  // split edge (its corners, ascending) -> its middle corner
    std::map<int, int> centre_of_;                  // flat-edge corner B -> the template's centre O on its face

    static std::array<int, 4> sorted(std::array<int, 4> c) { return std::sort(c.begin(), c.end()), c; }
    // The face through the frame's corners at the given frame indices.
    int face_of(const Frame& k, std::array<int, 4> ids) const {
        for (int& i : ids) i = k[size_t(i)];
        return face_of_.at(sorted(ids));
    }
    int face_at(const Frame& k, int z) const { return face_of(k, {at(0, 0, z), at(1, 0, z), at(1, 1, z), at(0, 1, z)}); }
    std::vector<std::vector<int>> face_users() const {
        std::vector<std::vector<int>> users(cx_.faces.size());
        for (int b = 0; b < int(cx_.blocks.size()); ++b)
            for (int f : cx_.blocks[size_t(b)].faces) users[size_t(f)].push_back(b);
        return users;
    }
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
        if (edge_of_.count(std::minmax(x, y))) return;  // a neighbour split by the same sheet made it
        std::vector<Eigen::Vector3d> pts;
        for (int i = 0; i < kStraightEdgePoints; ++i) {
            const double f = double(i) / (kStraightEdgePoints - 1);
            pts.push_back((1 - f) * cx_.corners[x].position + f * cx_.corners[y].position);
        }
        add_edge(x, y, pts, {});
    }
    void add_face(std::array<int, 4> corners, const ComplexFace* parent) {
        if (face_of_.count(sorted(corners))) return;
        face_of_[sorted(corners)] = int(cx_.faces.size());
        cx_.faces.push_back({corners, parent ? parent->triangles : std::vector<Eigen::Vector3i>{}, parent && parent->boundary});
    }
    // Splits the edge from x to y at its middle chain vertex: the new corner (the same one when
    // the edge was split before).
    int split_edge(int x, int y);
    // The blocks (index, local axis) a sheet must split that enters the neighbours across the
    // faces `starts` (face id, an edge of it along the sheet), away from block `flat`; nullopt
    // with `why` when the sheet comes back to `flat` or crosses a block along two axes.
    std::optional<std::vector<std::pair<int, int>>> sheet_blocks(const std::vector<int>& flat,
                                                                 const std::vector<std::pair<int, int>>& starts,
                                                                 std::string& why) const;
    // Splits block `bi` in two across local axis d, at the middles of its four edges along d.
    void split_block(int bi, int d);
    // The corners of block bi seen along its local edge e (frame indices at(x, y, z)).
    Frame frame_of(int bi, int e) const;
    // The blocks the flat edge of block bi (frame `first`) runs through, face to face, in order
    // along it, with their frames; nullopt with `why` where it cannot be followed. The others
    // need not be flat there: the template halves their corner at the edge.
    std::optional<std::vector<std::pair<int, Frame>>> flat_chain(int bi, const Frame& first, std::string& why) const;
    // The template's centre corner O on the frame's face at z, made once per face.
    int centre(const Frame& k, int z, int mad, int mcd);
    // The template: block bi (frame k) becomes three blocks around O.
    void three_blocks(int bi, const Frame& k);
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
    if (auto it = middle_of_.find(std::minmax(x, y)); it != middle_of_.end()) return it->second;
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
    middle_of_[std::minmax(x, y)] = c;
    return c;
}

std::optional<std::vector<std::pair<int, int>>> Splitter::sheet_blocks(const std::vector<int>& flat,
                                                                       const std::vector<std::pair<int, int>>& starts,
                                                                       std::string& why) const {
    const std::vector<std::vector<int>> users = face_users();
    std::map<int, int> axis_of;  // block -> the local axis the sheet crosses it along
    std::vector<std::pair<int, int>> queue(starts.begin(), starts.end()), plan;
    while (!queue.empty()) {
        const auto [f, e] = queue.back();
        queue.pop_back();
        for (int b : users[size_t(f)]) {
            const ComplexBlock& blk = cx_.blocks[size_t(b)];
            if (std::find(flat.begin(), flat.end(), b) != flat.end()) {
                if (std::none_of(starts.begin(), starts.end(), [&](auto s) { return s.first == f; }))
                    return why = "the sheet through its neighbours comes back to it", std::nullopt;
                continue;
            }
            const int local = int(std::find(blk.edges.begin(), blk.edges.end(), e) - blk.edges.begin());
            if (local == 12) return why = "block " + std::to_string(blk.id) + " does not have the sheet's edge", std::nullopt;
            const int d = local / 4;
            if (auto it = axis_of.find(b); it != axis_of.end()) {
                if (it->second != d) return why = "the sheet through its neighbours crosses block " + std::to_string(blk.id) + " twice", std::nullopt;
                continue;
            }
            axis_of[b] = d;
            plan.push_back({b, d});
            // On to the blocks across its four faces along d, each with one of its edges along d.
            for (int lf = 0; lf < 6; ++lf) {
                if (lf / 2 == d) continue;
                const auto fc = face_local_corners(lf);
                const int corner = fc[0], along = edge_at(corner, d);
                queue.push_back({blk.faces[size_t(lf)], blk.edges[size_t(along)]});
            }
        }
    }
    return plan;
}

void Splitter::split_block(int bi, int d) {
    const ComplexBlock old = cx_.blocks[size_t(bi)];
    std::array<int, 8> middle{};  // per local corner: the middle of the block's edge along d through it
    for (int l = 0; l < 8; ++l) {
        const auto ends = edge_local_corners(edge_at(l, d));
        middle[size_t(l)] = split_edge(old.corners[size_t(ends[0])], old.corners[size_t(ends[1])]);
    }
    for (int half = 0; half < 2; ++half) {
        std::array<int, 8> corners{};
        for (int l = 0; l < 8; ++l) corners[size_t(l)] = ((l >> d) & 1) == half ? old.corners[size_t(l)] : middle[size_t(l)];
        for (int e = 0; e < 12; ++e) {
            const auto l = edge_local_corners(e);
            add_straight_edge(corners[size_t(l[0])], corners[size_t(l[1])]);  // the halves of the split edges exist
        }
        for (int lf = 0; lf < 6; ++lf) {
            const auto l = face_local_corners(lf);
            const ComplexFace parent = cx_.faces[size_t(old.faces[size_t(lf)])];
            // A face across d is the old one or the new middle face, inside the block.
            add_face({corners[size_t(l[0])], corners[size_t(l[1])], corners[size_t(l[2])], corners[size_t(l[3])]},
                     lf / 2 == d ? nullptr : &parent);
        }
        const ComplexBlock b = cube(half == 0 ? old.id : int(cx_.blocks.size()), corners);
        if (half == 0) cx_.blocks[size_t(bi)] = b;
        else cx_.blocks.push_back(b);
    }
}

Frame Splitter::frame_of(int bi, int e) const {
    const ComplexBlock& b = cx_.blocks[size_t(bi)];
    // z along the flat edge, which sits at x = y = 0; right-handed like the block.
    const int d = e / 4, l0 = edge_local_corners(e)[0];
    std::array<int, 3> axis{(d + 1) % 3, (d + 2) % 3, d}, flip{(l0 >> ((d + 1) % 3)) & 1, (l0 >> ((d + 2) % 3)) & 1, 0};
    if ((flip[0] + flip[1]) % 2) std::swap(axis[0], axis[1]), std::swap(flip[0], flip[1]);
    Frame k{};
    for (int x = 0; x < 2; ++x)
        for (int y = 0; y < 2; ++y)
            for (int z = 0; z < 2; ++z) {
                int bits[3];
                bits[axis[0]] = x ^ flip[0], bits[axis[1]] = y ^ flip[1], bits[axis[2]] = z;
                k[size_t(at(x, y, z))] = b.corners[size_t(local_corner(bits[0], bits[1], bits[2]))];
            }
    return k;
}

std::optional<std::vector<std::pair<int, Frame>>> Splitter::flat_chain(int bi, const Frame& first, std::string& why) const {
    const std::vector<std::vector<int>> users = face_users();
    std::vector<std::pair<int, Frame>> chain{{bi, first}};
    for (int z = 0; z < 2; ++z) {  // on past the end at z = 1, then back past the one at z = 0
        for (;;) {
            const auto& [b, k] = z == 1 ? chain.back() : chain.front();
            const int f = face_at(k, z);
            if (cx_.faces[size_t(f)].boundary) break;
            const auto across = std::find_if(users[size_t(f)].begin(), users[size_t(f)].end(), [&](int u) { return u != b; });
            if (users[size_t(f)].size() != 2 || across == users[size_t(f)].end())
                return why = "a face at the ends of its flat edge is not shared with one block", std::nullopt;
            const int m = *across;
            if (std::any_of(chain.begin(), chain.end(), [&](const auto& c) { return c.first == m; }))
                return why = "its flat edge closes a ring of blocks", std::nullopt;
            // The neighbour's frame: the shared face at its own z = 1 - z, then across its block.
            const ComplexBlock& nb = cx_.blocks[size_t(m)];
            Frame km{};
            int d = -1;
            for (int x = 0; x < 2; ++x)
                for (int y = 0; y < 2; ++y) {
                    const int c = k[size_t(at(x, y, z))];
                    const int l = int(std::find(nb.corners.begin(), nb.corners.end(), c) - nb.corners.begin());
                    if (l == 8) return why = "its neighbour along the flat edge does not have the shared face's corners", std::nullopt;
                    km[size_t(at(x, y, 1 - z))] = c;
                    km[size_t(at(x, y, z))] = -1 - l;  // its local corner, resolved below
                }
            for (int a = 0; a < 3 && d < 0; ++a) {
                bool across_a = true;  // the shared face is at constant bit a of the neighbour
                for (int x = 0; x < 2; ++x)
                    for (int y = 0; y < 2; ++y)
                        across_a &= ((-1 - km[size_t(at(x, y, z))]) >> a & 1) == ((-1 - km[size_t(at(0, 0, z))]) >> a & 1);
                if (across_a) d = a;
            }
            for (int x = 0; x < 2; ++x)
                for (int y = 0; y < 2; ++y) km[size_t(at(x, y, z))] = nb.corners[size_t((-1 - km[size_t(at(x, y, z))]) ^ (1 << d))];
            const int flat_edge = int(std::find(nb.edges.begin(), nb.edges.end(), edge(km[size_t(at(0, 0, 0))], km[size_t(at(0, 0, 1))])) - nb.edges.begin());
            if (flat_edge == 12) return why = "block " + std::to_string(nb.id) + " does not continue its flat edge", std::nullopt;
            if (z == 1) chain.push_back({m, km});
            else chain.insert(chain.begin(), {m, km});
        }
    }
    return chain;
}

int Splitter::centre(const Frame& k, int z, int mad, int mcd) {
    const int b = k[size_t(at(0, 0, z))];
    if (auto it = centre_of_.find(b); it != centre_of_.end()) return it->second;
    // At the Fermat point of its three spokes' far ends, onto the face: the three angles at it are
    // 120 degrees (the Coons middle of the face left one near 145 on the notch).
    const ComplexFace face = cx_.faces[size_t(face_at(k, z))];
    const Eigen::Vector3d p =
        fermat_point({cx_.corners[size_t(b)].position, cx_.corners[size_t(mad)].position, cx_.corners[size_t(mcd)].position});
    if (!locator_) locator_.emplace(mesh_);
    const Eigen::Vector3d o = FaceProjector(mesh_, face, *locator_).project(p, {});
    const int vertex = nearest_vertex(mesh_, face, o);
    const int c = add_corner(o, vertex >= 0 ? std::vector<int>{vertex} : std::vector<int>{});
    centre_of_[b] = c;
    return c;
}

void Splitter::three_blocks(int bi, const Frame& k) {
    // Per end z: B on the flat edge, A and C its neighbours, D opposite; new corners mAD, mCD, O.
    std::array<int, 2> B, A, C, D, mAD, mCD, O;
    const ComplexFace x1 = cx_.faces[size_t(face_of(k, {at(1, 0, 0), at(1, 1, 0), at(1, 1, 1), at(1, 0, 1)}))];
    const ComplexFace y1 = cx_.faces[size_t(face_of(k, {at(0, 1, 0), at(1, 1, 0), at(1, 1, 1), at(0, 1, 1)}))];
    for (int z = 0; z < 2; ++z) {
        B[z] = k[size_t(at(0, 0, z))], A[z] = k[size_t(at(1, 0, z))], C[z] = k[size_t(at(0, 1, z))], D[z] = k[size_t(at(1, 1, z))];
        mAD[z] = split_edge(A[z], D[z]);
        mCD[z] = split_edge(C[z], D[z]);
        O[z] = centre(k, z, mAD[z], mCD[z]);
        const ComplexFace end = cx_.faces[size_t(face_at(k, z))];
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
    const int id = cx_.blocks[size_t(bi)].id;
    for (size_t q = 0; q < 3; ++q) {
        std::array<int, 8> corners{};
        const int order[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int n = 0; n < 4; ++n)
            for (int z = 0; z < 2; ++z) corners[size_t(local_corner(order[n][0], order[n][1], z))] = quads[q][size_t(n)][size_t(z)];
        const ComplexBlock b = cube(q == 0 ? id : int(cx_.blocks.size()), corners);
        if (q == 0) cx_.blocks[size_t(bi)] = b;
        else cx_.blocks.push_back(b);
    }
}

std::string Splitter::refine(int bi, int e) {
    std::string why;
    const auto chain = flat_chain(bi, frame_of(bi, e), why);
    if (!chain) return why;
    // The faces opposite the flat edge are split across their middles: a neighbour across one is
    // split the same way, by a sheet on through its neighbours to the boundary.
    std::vector<int> flat;
    std::vector<std::pair<int, int>> starts;
    for (const auto& [b, k] : *chain) {
        flat.push_back(b);
        const int x1 = face_of(k, {at(1, 0, 0), at(1, 1, 0), at(1, 1, 1), at(1, 0, 1)});
        const int y1 = face_of(k, {at(0, 1, 0), at(1, 1, 0), at(1, 1, 1), at(0, 1, 1)});
        if (!cx_.faces[size_t(x1)].boundary) starts.push_back({x1, edge(k[size_t(at(1, 0, 0))], k[size_t(at(1, 1, 0))])});
        if (!cx_.faces[size_t(y1)].boundary) starts.push_back({y1, edge(k[size_t(at(0, 1, 0))], k[size_t(at(1, 1, 0))])});
    }
    const auto plan = sheet_blocks(flat, starts, why);
    if (!plan) return why;
    for (const auto& [b, d] : *plan) split_block(b, d);
    for (const auto& [b, k] : *chain) three_blocks(b, k);
    return "";
}
}  // namespace

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

std::string refine_flat_block(const TetMesh& mesh, BlockComplex& cx, int bi, int e) {
    Splitter split(mesh, cx);
    const std::string why = split.refine(bi, e);
    if (why.empty()) compact(cx);
    return why;
}

}  // namespace framefix
