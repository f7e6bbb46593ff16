// gmsh .msh version 4 ASCII reader (format: gmsh reference manual, "MSH file format version 4").
#include <algorithm>
#include <climits>
#include <utility>
#include <vector>

#include "framefix/mesh/mesh_io.h"
#include "framefix/mesh/mesh_io_text.h"

namespace framefix {
namespace {

// Nodes per element for the gmsh element types we may meet (others are refused by name).
int nodes_of_type(int type) {
    switch (type) {
        case 1: return 2;   case 2: return 3;   case 3: return 4;   case 4: return 4;
        case 5: return 8;   case 6: return 6;   case 7: return 5;   case 8: return 3;
        case 9: return 6;   case 10: return 9;  case 11: return 10; case 12: return 27;
        case 13: return 18; case 14: return 14; case 15: return 1;  case 16: return 8;
        case 17: return 20; case 18: return 15; case 19: return 13;
        default: return -1;
    }
}

// gmsh node tag -> row. Tags are usually 1..n: then a dense table (a std::map's node chasing
// was half of the read time at 1M tets); sparse tags fall back to a sorted list.
class NodeRows {
public:
    void add(long long tag, int row) { pairs_.push_back({tag, row}); }
    void finish() {
        if (pairs_.empty()) return;
        lo_ = hi_ = pairs_[0].first;
        for (const auto& [tag, row] : pairs_) lo_ = std::min(lo_, tag), hi_ = std::max(hi_, tag);
        if (hi_ - lo_ < kDenseSlack * (long long)pairs_.size()) {
            dense_.assign(size_t(hi_ - lo_ + 1), -1);
            for (const auto& [tag, row] : pairs_) dense_[size_t(tag - lo_)] = row;
            pairs_.clear();
        } else {
            std::sort(pairs_.begin(), pairs_.end());
        }
    }
    int find(long long tag) const {  // -1: unknown
        if (!dense_.empty()) return tag < lo_ || tag > hi_ ? -1 : dense_[size_t(tag - lo_)];
        const auto it = std::lower_bound(pairs_.begin(), pairs_.end(), std::pair<long long, int>{tag, INT_MIN});
        return it != pairs_.end() && it->first == tag ? it->second : -1;
    }

private:
    static constexpr long long kDenseSlack = 4;  // a table at most 4 x the node count
    std::vector<std::pair<long long, int>> pairs_;
    std::vector<int> dense_;
    long long lo_ = 0, hi_ = 0;
};

void skip_section(TextTokens& tok, const std::string& name) {
    const std::string end = "$End" + name.substr(1);
    while (tok.word() != end) {}
}

}  // namespace

TetMesh read_msh(const std::string& path) {
    TextTokens tok(path);
    if (tok.word() != "$MeshFormat") tok.fail("not a gmsh .msh file (no $MeshFormat header)");
    const std::string version = tok.word();
    const long long file_type = tok.integer();
    tok.word();  // data size
    if (version.empty() || version[0] < '4')
        tok.fail("msh version " + version + " is not supported; save as version 4 (gmsh -format msh4)");
    if (file_type != 0) tok.fail("binary .msh is not supported; save as ASCII (gmsh option Mesh.Binary=0)");
    if (tok.word() != "$EndMeshFormat") tok.fail("malformed $MeshFormat section");

    Points points(0, 3);
    NodeRows node_index;
    std::vector<std::array<long long, 4>> tets;
    std::vector<std::array<long long, 3>> tris;
    std::vector<int> tri_tags;
    bool have_nodes = false, have_elements = false;
    const long long limit = tok.max_items();
    while (!tok.at_end()) {
        const std::string section = tok.word();
        if (section.empty() || section[0] != '$') tok.fail("expected a $Section, found '" + section + "'");
        if (section == "$Nodes") {
            const int blocks = tok.count(limit, "node block");
            const int n = tok.count(limit, "node");
            tok.integer();
            tok.integer();
            points.resize(n, 3);
            int row = 0;
            for (int b = 0; b < blocks; ++b) {
                const long long dim = tok.integer();
                tok.integer();
                const long long parametric = tok.integer();
                const int m = tok.count(limit, "node");
                if (row + m > n) tok.fail("node blocks hold more nodes than announced");
                for (int i = 0; i < m; ++i) node_index.add(tok.integer(), row + i);
                for (int i = 0; i < m; ++i) {
                    for (int k = 0; k < 3; ++k) points(row + i, k) = tok.real();
                    for (long long k = 0; parametric && k < dim; ++k) tok.real();
                }
                row += m;
            }
            if (row != n) tok.fail("node blocks hold fewer nodes than announced");
            if (tok.word() != "$EndNodes") tok.fail("malformed $Nodes section");
            have_nodes = true;
        } else if (section == "$Elements") {
            const int blocks = tok.count(limit, "element block");
            tok.integer();
            tok.integer();
            tok.integer();
            for (int b = 0; b < blocks; ++b) {
                const long long dim = tok.integer();
                const long long entity = tok.integer();
                const int type = int(tok.integer());
                const int m = tok.count(limit, "element");
                const int nn = nodes_of_type(type);
                if (nn < 0) tok.fail("unsupported element type " + std::to_string(type));
                if (dim == 3 && type != 4 && type != 11)
                    tok.fail("the volume mesh has non-tet elements (gmsh type " + std::to_string(type) + "); a tet mesh is needed");
                for (int i = 0; i < m; ++i) {
                    tok.integer();
                    long long v[27];
                    for (int k = 0; k < nn; ++k) v[k] = tok.integer();
                    if (dim == 3) tets.push_back({v[0], v[1], v[2], v[3]});  // tet10: the corners come first
                    else if (dim == 2 && (type == 2 || type == 9)) {
                        tris.push_back({v[0], v[1], v[2]});
                        tri_tags.push_back(int(entity));
                    }
                }
            }
            if (tok.word() != "$EndElements") tok.fail("malformed $Elements section");
            have_elements = true;
        } else {
            skip_section(tok, section);
        }
    }
    if (!have_nodes || !have_elements) tok.fail("the file has no $Nodes or no $Elements section");

    node_index.finish();
    auto lookup = [&](long long tag) {
        const int row = node_index.find(tag);
        if (row < 0) tok.fail("an element refers to the unknown node " + std::to_string(tag));
        return row;
    };
    Tets T(int(tets.size()), 4);
    for (int t = 0; t < T.rows(); ++t)
        for (int k = 0; k < 4; ++k) T(t, k) = lookup(tets[t][k]);
    Triangles F(int(tris.size()), 3);
    for (int f = 0; f < F.rows(); ++f)
        for (int k = 0; k < 3; ++k) F(f, k) = lookup(tris[f][k]);
    return assemble_tet_mesh(std::move(points), std::move(T), F, Eigen::Map<Eigen::VectorXi>(tri_tags.data(), int(tri_tags.size())));
}

}  // namespace framefix
