// The closed quad mesh of an axis-aligned box of nx * ny * nz voxels, one unit quad per voxel
// face, welded lattice vertices, counter-clockwise seen from outside: what the surface
// extraction (section 4.2) yields for a box, built directly so unit tests need no extraction.
#pragma once

#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

#include <glm/vec3.hpp>

namespace voxelfair::shapes {

struct QuadMesh {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> offsets;  // quadCount + 1: 0, 4, 8, ...
    std::vector<uint32_t> indices;  // 4 per quad

    size_t quadCount() const { return offsets.empty() ? 0 : offsets.size() - 1; }
    // Index of the vertex at lattice point (x, y, z); -1 when there is none.
    int find(int x, int y, int z) const {
        for (size_t v = 0; v < positions.size(); ++v)
            if (positions[v] == glm::vec3(float(x), float(y), float(z)))
                return int(v);
        return -1;
    }
};

inline QuadMesh boxLattice(int nx, int ny, int nz) {
    QuadMesh mesh;
    std::map<std::tuple<int, int, int>, uint32_t> index;
    auto vertex = [&](int p[3]) {
        auto [it, added] = index.emplace(std::make_tuple(p[0], p[1], p[2]), uint32_t(mesh.positions.size()));
        if (added)
            mesh.positions.emplace_back(float(p[0]), float(p[1]), float(p[2]));
        return it->second;
    };
    const int n[3] = {nx, ny, nz};
    mesh.offsets.push_back(0);
    for (int a = 0; a < 3; ++a) {
        const int b = (a + 1) % 3, c = (a + 2) % 3;  // b x c = a
        for (int side = 0; side < 2; ++side)
            for (int i = 0; i < n[b]; ++i)
                for (int j = 0; j < n[c]; ++j) {
                    // Counter-clockwise about +a in the (b, c) plane; reversed on the low side.
                    const int corner[4][2] = {{i, j}, {i + 1, j}, {i + 1, j + 1}, {i, j + 1}};
                    uint32_t quad[4];
                    for (int k = 0; k < 4; ++k) {
                        int p[3];
                        p[a] = side ? n[a] : 0;
                        p[b] = corner[k][0];
                        p[c] = corner[k][1];
                        quad[k] = vertex(p);
                    }
                    if (side)
                        mesh.indices.insert(mesh.indices.end(), {quad[0], quad[1], quad[2], quad[3]});
                    else
                        mesh.indices.insert(mesh.indices.end(), {quad[0], quad[3], quad[2], quad[1]});
                    mesh.offsets.push_back(uint32_t(mesh.indices.size()));
                }
    }
    return mesh;
}

}  // namespace voxelfair::shapes
