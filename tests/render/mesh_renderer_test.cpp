#include "render/mesh_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <vector>

#include <glm/vec4.hpp>

using namespace voxelfair::render;

namespace {

// Where a model-space point lands in the picture (pixel column, row from the top).
glm::ivec2 pixelOf(const View &view, const glm::vec3 &p, int width, int height) {
    const glm::vec4 clip = view.projection * view.view * glm::vec4(p, 1.0f);
    return {int((clip.x / clip.w * 0.5f + 0.5f) * float(width)), int((0.5f - clip.y / clip.w * 0.5f) * float(height))};
}

bool near(glm::u8vec3 a, glm::u8vec3 b, int tolerance) {
    for (int c = 0; c < 3; ++c)
        if (std::abs(int(a[c]) - int(b[c])) > tolerance)
            return false;
    return true;
}

// Unlit: the picture shows the albedo itself.
RenderOptions unlit(int size) {
    RenderOptions o;
    o.width = o.height = size;
    o.lighting.ambient = 1.0f;
    o.lighting.diffuse = 0.0f;
    o.lighting.specular = 0.0f;
    return o;
}

// Unit cube [0,1]^3 as 12 outward triangles, two per face, faces in the order +x -x +y -y +z -z.
struct Cube {
    std::vector<glm::vec3> positions;
    std::vector<uint32_t> triangles;
    Cube() {
        for (int i = 0; i < 8; ++i)
            positions.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
        const uint32_t quads[6][4] = {{1, 3, 7, 5}, {0, 4, 6, 2}, {2, 6, 7, 3},
                                      {0, 1, 5, 4}, {4, 5, 7, 6}, {0, 2, 3, 1}};
        for (const auto &q : quads)
            for (uint32_t k : {q[0], q[1], q[2], q[0], q[2], q[3]})
                triangles.push_back(k);
    }
    RenderMesh mesh() const {
        RenderMesh m;
        m.positions = positions.data();
        m.vertexCount = positions.size();
        m.triangles = triangles.data();
        m.triangleCount = triangles.size() / 3;
        return m;
    }
};

TEST(MeshRenderer, CubeShowsItsThreeFrontFacesOnTheBackground) {
    // Seen from +x, -y, +z: faces +x (red), -y (magenta), +z (blue) face the eye; the hidden
    // ones are green, and no mix of the visible colours with the grey background is green.
    const Cube cube;
    const std::array<glm::u8vec3, 6> faceColour = {glm::u8vec3{255, 0, 0}, {0, 255, 0}, {20, 255, 20},
                                                   {255, 0, 255},          {0, 0, 255}, {40, 255, 40}};
    std::vector<glm::u8vec3> triangleColours;
    for (const glm::u8vec3 &c : faceColour)
        triangleColours.insert(triangleColours.end(), 2, c);
    RenderMesh mesh = cube.mesh();
    mesh.faceColours = triangleColours.data();

    RenderOptions options;  // lit: Lambert, ambient and specular
    options.width = options.height = 200;
    options.lighting.specular = 0.0f;  // keeps the face hues pure for the checks
    const Camera camera;               // azimuth -35, elevation 28
    const View view = fitView(cube.positions.data(), cube.positions.size(), camera, 1.0f);
    const Image image = renderMesh(mesh, view, options);
    ASSERT_EQ(image.width, 200);
    ASSERT_EQ(image.height, 200);

    for (glm::ivec2 corner : {glm::ivec2(0, 0), glm::ivec2(199, 0), glm::ivec2(0, 199), glm::ivec2(199, 199)})
        EXPECT_EQ(image.pixel(corner.x, corner.y), options.background);

    // Each visible face's centre shows that face's hue, lit (neither black nor clipped white).
    const struct {
        glm::vec3 centre;
        int face;
    } visible[] = {{{1.0f, 0.5f, 0.5f}, 0}, {{0.5f, 0.0f, 0.5f}, 3}, {{0.5f, 0.5f, 1.0f}, 4}};
    for (const auto &v : visible) {
        const glm::ivec2 at = pixelOf(view, v.centre, image.width, image.height);
        const glm::u8vec3 p = image.pixel(at.x, at.y);
        for (int c = 0; c < 3; ++c) {
            if (faceColour[size_t(v.face)][c] == 0)
                EXPECT_EQ(p[c], 0) << "face " << v.face << " channel " << c;
            else
                EXPECT_GT(p[c], 60) << "face " << v.face << " channel " << c;
        }
    }
    // The three faces are lit differently (the key light comes from above left).
    const glm::u8vec3 right =
        image.pixel(pixelOf(view, visible[0].centre, 200, 200).x, pixelOf(view, visible[0].centre, 200, 200).y);
    const glm::u8vec3 top =
        image.pixel(pixelOf(view, visible[2].centre, 200, 200).x, pixelOf(view, visible[2].centre, 200, 200).y);
    EXPECT_NE(right.r, top.b);

    size_t hidden = 0, model = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const glm::u8vec3 p = image.pixel(x, y);
            hidden += p.g > std::max(p.r, p.b) + 8;
            model += p != options.background;
        }
    EXPECT_EQ(hidden, 0u);
    EXPECT_GT(model, size_t(200 * 200 / 4));
}

TEST(MeshRenderer, FitViewFramesTheModelWithTheMargin) {
    const Cube cube;
    Camera camera;
    camera.margin = 0.1f;
    const View view = fitView(cube.positions.data(), cube.positions.size(), camera, 1.0f);
    const Image image = renderMesh(cube.mesh(), view, unlit(200));
    int left = 200, right = -1, top = 200, bottom = -1;
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 200; ++x)
            if (image.pixel(x, y) != RenderOptions{}.background) {
                left = std::min(left, x), right = std::max(right, x);
                top = std::min(top, y), bottom = std::max(bottom, y);
            }
    // The larger extent touches the margin (20 px); the other is centred.
    const int gapX = std::min(left, 199 - right), gapY = std::min(top, 199 - bottom);
    EXPECT_NEAR(std::min(gapX, gapY), 20, 2);
    EXPECT_NEAR(left, 199 - right, 2);
    EXPECT_NEAR(top, 199 - bottom, 2);
}

TEST(MeshRenderer, NearerTriangleWinsWhateverTheDrawingOrder) {
    // Two squares facing +x (the eye), the red one nearer; drawn in both orders.
    const std::vector<glm::vec3> positions = {{0, 0, 0},
                                              {0, 1, 0},
                                              {0, 1, 1},
                                              {0, 0, 1},
                                              {0.5f, 0.25f, 0.25f},
                                              {0.5f, 0.75f, 0.25f},
                                              {0.5f, 0.75f, 0.75f},
                                              {0.5f, 0.25f, 0.75f}};
    const std::vector<glm::u8vec3> farFirst = {{0, 0, 255}, {0, 0, 255}, {255, 0, 0}, {255, 0, 0}};
    const std::vector<glm::u8vec3> nearFirst = {{255, 0, 0}, {255, 0, 0}, {0, 0, 255}, {0, 0, 255}};
    const std::vector<uint32_t> farThenNear = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7};
    const std::vector<uint32_t> nearThenFar = {4, 5, 6, 4, 6, 7, 0, 1, 2, 0, 2, 3};
    Camera camera;
    camera.azimuthDeg = 0.0f;
    camera.elevationDeg = 0.0f;
    const View view = fitView(positions.data(), positions.size(), camera, 1.0f);
    for (int order = 0; order < 2; ++order) {
        RenderMesh mesh;
        mesh.positions = positions.data();
        mesh.vertexCount = positions.size();
        mesh.triangles = order == 0 ? farThenNear.data() : nearThenFar.data();
        mesh.triangleCount = 4;
        mesh.faceColours = order == 0 ? farFirst.data() : nearFirst.data();
        const Image image = renderMesh(mesh, view, unlit(120));
        const glm::ivec2 centre = pixelOf(view, {0.5f, 0.5f, 0.5f}, 120, 120);
        const glm::ivec2 rim = pixelOf(view, {0.0f, 0.1f, 0.5f}, 120, 120);
        EXPECT_EQ(image.pixel(centre.x, centre.y), glm::u8vec3(255, 0, 0)) << "order " << order;
        EXPECT_EQ(image.pixel(rim.x, rim.y), glm::u8vec3(0, 0, 255)) << "order " << order;
    }
}

// A unit square in the plane x = 0, seen from +x with z up: u runs along +y (picture right) and
// v along +z (picture up), so the texture appears upright.
struct TexturedSquare {
    std::vector<glm::vec3> positions = {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}};
    std::vector<uint32_t> triangles = {0, 1, 2, 0, 2, 3};
    std::vector<glm::vec2> wedgeUv = {{0, 0}, {1, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 1}};
    Camera camera;
    View view;
    TexturedSquare() {
        camera.azimuthDeg = 0.0f;
        camera.elevationDeg = 0.0f;
        view = fitView(positions.data(), positions.size(), camera, 1.0f);
    }
};

TEST(MeshRenderer, TexturedSquareShowsEachTexelWhereItsUvLies) {
    // 4 x 4 texels, rows from the top, all different.
    constexpr int n = 4;
    std::vector<uint8_t> rgba;
    auto texelColour = [](int x, int row) { return glm::u8vec3(40 + 60 * x, 40 + 60 * row, 255 - 30 * (x + row)); };
    for (int row = 0; row < n; ++row)
        for (int x = 0; x < n; ++x) {
            const glm::u8vec3 c = texelColour(x, row);
            rgba.insert(rgba.end(), {c.r, c.g, c.b, 255});
        }
    const TexturedSquare square;
    RenderMesh mesh;
    mesh.positions = square.positions.data();
    mesh.vertexCount = 4;
    mesh.triangles = square.triangles.data();
    mesh.triangleCount = 2;
    mesh.wedgeUv = square.wedgeUv.data();
    mesh.texture = {n, n, rgba.data()};
    mesh.faceColours = nullptr;
    const Image image = renderMesh(mesh, square.view, unlit(256));
    for (int row = 0; row < n; ++row)
        for (int x = 0; x < n; ++x) {
            // Texel centre: u = (x + 0.5) / n, v = 1 - (row + 0.5) / n, i.e. model (0, u, v).
            const glm::vec3 p(0.0f, (x + 0.5f) / n, 1.0f - (row + 0.5f) / n);
            const glm::ivec2 at = pixelOf(square.view, p, 256, 256);
            EXPECT_TRUE(near(image.pixel(at.x, at.y), texelColour(x, row), 2))
                << "texel " << x << "," << row << " at pixel " << at.x << "," << at.y;
        }
    // Halfway between two texels, bilinear filtering blends them evenly.
    const glm::ivec2 between = pixelOf(square.view, {0.0f, 0.5f, 1.0f - 0.5f / n}, 256, 256);
    const glm::vec3 expected = 0.5f * (glm::vec3(texelColour(1, 0)) + glm::vec3(texelColour(2, 0)));
    EXPECT_TRUE(near(image.pixel(between.x, between.y), glm::u8vec3(expected + 0.5f), 4));
}

TEST(MeshRenderer, VertexColoursAreInterpolatedPerspectiveCorrectly) {
    const TexturedSquare square;
    const std::vector<glm::u8vec3> colours = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}, {0, 0, 255}};
    RenderMesh mesh;
    mesh.positions = square.positions.data();
    mesh.vertexCount = 4;
    mesh.triangles = square.triangles.data();
    mesh.triangleCount = 1;  // the first triangle only: red, green, blue corners
    mesh.vertexColours = colours.data();
    const Image image = renderMesh(mesh, square.view, unlit(240));
    const glm::vec3 centroid = (square.positions[0] + square.positions[1] + square.positions[2]) / 3.0f;
    const glm::ivec2 at = pixelOf(square.view, centroid, 240, 240);
    EXPECT_TRUE(near(image.pixel(at.x, at.y), glm::u8vec3(85, 85, 85), 3));
    const glm::ivec2 corner = pixelOf(square.view, {0.0f, 0.97f, 0.02f}, 240, 240);  // near the green corner
    EXPECT_GT(image.pixel(corner.x, corner.y).g, 200);
}

TEST(MeshRenderer, WireframeDrawsPolygonEdgesButNotFanDiagonals) {
    const TexturedSquare square;
    const uint32_t offsets[] = {0, 4};
    const std::vector<uint8_t> mask = fanEdgeMask(offsets, 1);
    ASSERT_EQ(mask, (std::vector<uint8_t>{0b011, 0b110}));
    RenderMesh mesh;
    mesh.positions = square.positions.data();
    mesh.vertexCount = 4;
    mesh.triangles = square.triangles.data();
    mesh.triangleCount = 2;
    mesh.edgeMask = mask.data();
    mesh.flatColour = {250, 250, 250};
    RenderOptions options = unlit(200);
    options.wireWidth = 3.0f;
    options.wireOpacity = 1.0f;
    const Image image = renderMesh(mesh, square.view, options);
    const glm::ivec2 onDiagonal = pixelOf(square.view, {0.0f, 0.5f, 0.5f}, 200, 200);
    const glm::ivec2 onEdge = pixelOf(square.view, {0.0f, 0.5f, 0.003f}, 200, 200);
    EXPECT_EQ(image.pixel(onDiagonal.x, onDiagonal.y), mesh.flatColour);
    EXPECT_EQ(image.pixel(onEdge.x, onEdge.y), options.wireColour);
}

TEST(MeshRenderer, FanEdgeMaskOfMixedPolygons) {
    // A triangle (one fan triangle, all edges) then a pentagon (three fan triangles).
    const uint32_t offsets[] = {0, 3, 8};
    EXPECT_EQ(fanEdgeMask(offsets, 2), (std::vector<uint8_t>{0b111, 0b011, 0b010, 0b110}));
}

TEST(MeshRenderer, SkipsBadIndicesAndNonFiniteVertices) {
    const std::vector<glm::vec3> positions = {{0, 0, 0}, {0, 1, 0}, {0, 1, 1}, {0, 0, 1}, {NAN, 0, 0}};
    const std::vector<uint32_t> triangles = {0, 1, 2, 0, 2, 9, 0, 4, 3};
    RenderMesh mesh;
    mesh.positions = positions.data();
    mesh.vertexCount = positions.size();
    mesh.triangles = triangles.data();
    mesh.triangleCount = 3;
    Camera camera;
    camera.azimuthDeg = 0.0f;
    camera.elevationDeg = 0.0f;
    const View view = fitView(positions.data(), positions.size(), camera, 1.0f);
    const Image image = renderMesh(mesh, view, unlit(64));
    const glm::ivec2 drawn = pixelOf(view, {0.0f, 0.7f, 0.3f}, 64, 64);
    const glm::ivec2 skipped = pixelOf(view, {0.0f, 0.2f, 0.7f}, 64, 64);
    EXPECT_EQ(image.pixel(drawn.x, drawn.y), mesh.flatColour);
    EXPECT_EQ(image.pixel(skipped.x, skipped.y), RenderOptions{}.background);
}

TEST(MeshRenderer, SideBySideKeepsEachImage) {
    Image a, b;
    a.width = 2, a.height = 2, a.rgb.assign(12, 10);
    b.width = 3, b.height = 4, b.rgb.assign(36, 20);
    const Image both = sideBySide({a, b}, 1, {0, 0, 0});
    ASSERT_EQ(both.width, 6);
    ASSERT_EQ(both.height, 4);
    EXPECT_EQ(both.pixel(0, 1), glm::u8vec3(10));
    EXPECT_EQ(both.pixel(0, 0), glm::u8vec3(0));  // a is centred vertically
    EXPECT_EQ(both.pixel(2, 1), glm::u8vec3(0));  // the gap
    EXPECT_EQ(both.pixel(5, 3), glm::u8vec3(20));
}

}  // namespace
