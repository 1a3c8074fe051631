// Section 4.5's texel rasteriser (atlas/texel_raster.h): conservative and centre spans against
// their texel-by-texel definitions, far from the origin and on slivers, and the top-left rule.
#include "atlas/texel_raster.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include <glm/common.hpp>

using namespace voxelfair;

TEST(TexelRaster, ConservativeCoverageOfAnAxisAlignedTriangle) {
    std::set<std::pair<int, int>> got;
    rasterConservative({1, 1}, {4, 1}, {1, 4}, -1.0 / 256, 8, 8, [&](int x, int y) { got.insert({x, y}); });
    // Texels meeting the triangle with positive area: the lower-left staircase, diagonal included.
    const std::set<std::pair<int, int>> want = {{1, 1}, {2, 1}, {3, 1}, {1, 2}, {2, 2}, {1, 3}};
    EXPECT_EQ(got, want);
    got.clear();
    rasterConservative({1, 1}, {4, 1}, {1, 4}, +1.0 / 256, 8, 8, [&](int x, int y) { got.insert({x, y}); });
    EXPECT_GT(got.size(), want.size());  // a positive margin also takes the touching texels
}

TEST(TexelRaster, SpansMatchTheTexelByTexelDefinition) {
    // The definition: the texel square grown by the margin meets the closed triangle, tested as
    // the triangle's box and its three edge half-planes.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coord(-3, 40);
    for (int trial = 0; trial < 2000; ++trial) {
        glm::dvec2 p[3] = {{coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}};
        if (trial % 3 == 0)  // small triangles with vertices on texel corners
            for (glm::dvec2 &q : p)
                q = glm::floor(p[0]) + glm::floor(q / 8.0);
        if (trial % 3 == 1)  // vertices on texel centres: edges through centres, the top-left rule's case
            for (glm::dvec2 &q : p)
                q = glm::floor(q / 4.0) + 0.5;
        if (doubleArea(p[0], p[1], p[2]) < 0)
            std::swap(p[1], p[2]);
        if (doubleArea(p[0], p[1], p[2]) == 0)
            continue;
        const double margin = trial % 2 ? 1.0 / 256 : -1.0 / 256;
        std::set<std::pair<int, int>> spans, reference;
        rasterConservative(p[0], p[1], p[2], margin, 37, 37, [&](int x, int y) { spans.insert({x, y}); });
        const glm::dvec2 lo = glm::min(p[0], glm::min(p[1], p[2])), hi = glm::max(p[0], glm::max(p[1], p[2]));
        for (int y = 0; y < 37; ++y)
            for (int x = 0; x < 37; ++x) {
                if (x + 1 + margin < lo.x || x - margin > hi.x || y + 1 + margin < lo.y || y - margin > hi.y)
                    continue;
                bool in = true;
                for (int i = 0; i < 3; ++i) {
                    const glm::dvec2 a = p[i], e = p[(i + 1) % 3] - p[i];
                    const double at = e.x * (y + 0.5 - a.y) - e.y * (x + 0.5 - a.x);
                    in = in && at + (0.5 + margin) * (std::abs(e.x) + std::abs(e.y)) >= 0;
                }
                if (in)
                    reference.insert({x, y});
            }
        ASSERT_EQ(spans, reference) << "trial " << trial;

        // Centres: strictly inside, or on a top or left edge.
        std::set<std::pair<int, int>> centres, centreReference;
        rasterCentres(p[0], p[1], p[2], 37, 37, [&](int x, int y) { centres.insert({x, y}); });
        for (int y = 0; y < 37; ++y)
            for (int x = 0; x < 37; ++x) {
                bool in = true;
                for (int i = 0; i < 3; ++i) {
                    const glm::dvec2 a = p[i], e = p[(i + 1) % 3] - p[i];
                    const double at = e.x * (y + 0.5 - a.y) - e.y * (x + 0.5 - a.x);
                    in = in && (at > 0 || (at == 0 && (e.y < 0 || (e.y == 0 && e.x < 0))));
                }
                if (in)
                    centreReference.insert({x, y});
            }
        ASSERT_EQ(centres, centreReference) << "trial " << trial;
    }
}

// The rows are solved in closed form and only settled texel by texel where rounding could
// matter: far from the origin (a 16384 texture), slivers, nearly horizontal and vertical edges,
// edges through texel centres and corners. Each row, conservative and centre spans alike, must
// be exactly the texels the per-texel tests accept, and rasterRows the two together.
TEST(TexelRaster, SolvedRowsMatchThePerTexelTestsFarOutAndOnSlivers) {
    std::mt19937 rng(29);
    std::uniform_real_distribution<double> unit(0, 1);
    const int side = 16384;
    for (int trial = 0; trial < 6000; ++trial) {
        const glm::dvec2 origin(std::floor(unit(rng) * (side - 64)), std::floor(unit(rng) * (side - 64)));
        glm::dvec2 p[3];
        for (glm::dvec2 &q : p)
            q = origin + glm::dvec2(unit(rng), unit(rng)) * 40.0;
        switch (trial % 6) {
        case 0:  // a sliver: the third corner near the first two's line
            p[2] = p[0] + (p[1] - p[0]) * unit(rng) + glm::dvec2(1e-3, -2e-3) * unit(rng);
            break;
        case 1:  // a nearly horizontal edge
            p[1] = glm::dvec2(p[0].x + 30, p[0].y + 1e-9 * unit(rng));
            break;
        case 2:  // corners on texel centres
            for (glm::dvec2 &q : p)
                q = glm::floor(q / 3.0) * 3.0 + 0.5;
            break;
        case 3:  // corners on texel corners
            for (glm::dvec2 &q : p)
                q = glm::floor(q / 5.0) * 5.0;
            break;
        case 4:  // a nearly vertical edge
            p[1] = glm::dvec2(p[0].x + 1e-9 * unit(rng), p[0].y + 30);
            break;
        default: break;
        }
        if (doubleArea(p[0], p[1], p[2]) == 0)
            continue;
        const double margin = trial % 2 ? 1.0 / 256 : -1.0 / 256;
        std::set<std::pair<int, int>> spans, centres, rowsConservative, rowsCentres, reference, centreReference;
        rasterConservative(p[0], p[1], p[2], margin, side, side, [&](int x, int y) { spans.insert({x, y}); });
        rasterCentres(p[0], p[1], p[2], side, side, [&](int x, int y) { centres.insert({x, y}); });
        rasterRows(p[0], p[1], p[2], margin, side, side, [&](int y, int cl, int cr, int zl, int zr) {
            for (int x = cl; x <= cr; ++x)
                rowsConservative.insert({x, y});
            for (int x = zl; x <= zr; ++x)
                rowsCentres.insert({x, y});
        });
        glm::dvec2 q[3] = {p[0], p[1], p[2]};
        if (doubleArea(q[0], q[1], q[2]) < 0)
            std::swap(q[1], q[2]);
        const glm::dvec2 lo = glm::min(q[0], glm::min(q[1], q[2])), hi = glm::max(q[0], glm::max(q[1], q[2]));
        for (int y = int(lo.y) - 2; y <= int(hi.y) + 2; ++y)
            for (int x = int(lo.x) - 2; x <= int(hi.x) + 2; ++x) {
                bool in = x + 1 + margin >= lo.x && x - margin <= hi.x && y + 1 + margin >= lo.y && y - margin <= hi.y;
                bool centre = true;
                for (int i = 0; i < 3; ++i) {
                    const glm::dvec2 a = q[i], e = q[(i + 1) % 3] - q[i];
                    const double at = e.x * (y + 0.5 - a.y) - e.y * (x + 0.5 - a.x);
                    in = in && at + (0.5 + margin) * (std::abs(e.x) + std::abs(e.y)) >= 0;
                    centre = centre && (at > 0 || (at == 0 && (e.y < 0 || (e.y == 0 && e.x < 0))));
                }
                if (in)
                    reference.insert({x, y});
                if (centre)
                    centreReference.insert({x, y});
            }
        ASSERT_EQ(spans, reference) << "trial " << trial;
        ASSERT_EQ(centres, centreReference) << "trial " << trial;
        ASSERT_EQ(rowsConservative, reference) << "trial " << trial;
        ASSERT_EQ(rowsCentres, centreReference) << "trial " << trial;
    }
}

TEST(TexelRaster, TopLeftRuleCoversEachCentreOnce) {
    // A square split along its diagonal, which passes through texel centres.
    std::vector<int> count(64, 0);
    auto add = [&](int x, int y) { ++count[size_t(y) * 8 + x]; };
    rasterCentres({0.5, 0.5}, {6.5, 0.5}, {6.5, 6.5}, 8, 8, add);
    rasterCentres({0.5, 0.5}, {6.5, 6.5}, {0.5, 6.5}, 8, 8, add);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            // Centres on the square's left and top edges count, on its right and bottom not.
            EXPECT_EQ(count[size_t(y) * 8 + x], x <= 5 && y >= 1 && y <= 6 ? 1 : 0) << x << "," << y;
}
