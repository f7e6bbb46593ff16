#pragma once
// Blocks on the cube grid of tests/backend/mesh/cube_fixture.h: its topology, the surface group of
// each topology face (the cube face's tag on the boundary, -1 inside), h, and blocks given by a
// label per tet centroid, validated.
#include <unordered_map>
#include <vector>

#include "backend/mesh/cube_fixture.h"
#include "framefix/blocks/validation.h"
#include "framefix/mesh/keys.h"

namespace framefix::testing {

struct CubeBlocks {
    TetMesh mesh;
    TetTopology topo;
    std::vector<int> group;
    double h = 0;
    BlockDecomposition blocks;
    Validated v;
};

inline CubeBlocks cube_blocks(int cells) {
    CubeBlocks c;
    c.mesh = cube_tets(cells).mesh;
    c.topo = build_topology(c.mesh);
    std::unordered_map<TriangleKey, int, TriangleKeyHash> tag_of;
    const Triangles& bf = c.mesh.boundary_faces;
    for (int b = 0; b < int(bf.rows()); ++b) tag_of[triangle_key(bf(b, 0), bf(b, 1), bf(b, 2))] = c.mesh.face_tags(b);
    c.group.assign(size_t(c.topo.faces.rows()), -1);
    for (int f = 0; f < int(c.topo.faces.rows()); ++f)
        if (c.topo.face_tets(f, 1) < 0)
            c.group[size_t(f)] = tag_of.at(triangle_key(c.topo.faces(f, 0), c.topo.faces(f, 1), c.topo.faces(f, 2)));
    c.h = mean_edge_length(c.mesh, c.topo, 1);
    return c;
}

// Blocks 0..count-1 by label(tet centroid), validated, conformity counted.
template <class Label>
void label_blocks(CubeBlocks& c, int count, Label label) {
    c.blocks.count = count;
    c.blocks.tet_block.resize(c.mesh.num_tets());
    for (int t = 0; t < c.mesh.num_tets(); ++t) c.blocks.tet_block[t] = label(tet_centroid(c.mesh, t));
    c.v = validate_blocks(c.mesh, c.topo, c.group, c.h, BlockOptions{}, c.blocks);
    count_conformity(c.v, c.h, BlockOptions{}, c.blocks);
}

}  // namespace framefix::testing
