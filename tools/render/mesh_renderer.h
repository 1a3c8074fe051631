// A small offscreen software renderer for the report's pictures and for tests: one triangle mesh,
// z-buffered, perspective-correct, Lambert + ambient + a little Blinn-Phong specular, coloured by
// a texture, per-vertex colours or per-face colours, with an optional wireframe of polygon edges.
// Supersampled (box-filtered) for smooth edges. No OpenGL, no Qt: it runs anywhere the tests do.
//
//   View view = fitView(raw.positions, raw.vertexCount, Camera{}, 640.0f / 480.0f);  // once
//   Image a = renderMesh(raw, view, options), b = renderMesh(smoothed, view, options);
//   writePng("a.png", a.rgb.data(), a.width, a.height, 3);
//
// Models are z-up (VXL and VOX): the orbit camera turns around +z.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/gtc/type_precision.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace voxelfair::render {

// RGB8 image, rows from the top.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgb;

    glm::u8vec3 pixel(int x, int y) const {
        const uint8_t *p = &rgb[(size_t(y) * size_t(width) + size_t(x)) * 3];
        return {p[0], p[1], p[2]};
    }
};

// An RGBA8 texture, rows from the top (v = 1) down, like atlas/bake.h's AtlasTexture and PNG.
// Texel (x, y-from-top) covers u in [x, x+1] / width, v in [height - y - 1, height - y] / height.
struct Texture {
    int width = 0;
    int height = 0;
    const uint8_t *rgba = nullptr;  // not owned
};

// A triangle mesh on caller-owned arrays (nothing is copied). Colour: the first source given of
// texture (needs wedgeUv), vertexColours, faceColours; else flatColour.
struct RenderMesh {
    const glm::vec3 *positions = nullptr;
    size_t vertexCount = 0;
    const uint32_t *triangles = nullptr;  // 3 per triangle; either winding is drawn (two-sided)
    size_t triangleCount = 0;

    const glm::vec2 *wedgeUv = nullptr;  // 3 per triangle, v up
    Texture texture;
    const glm::u8vec3 *vertexColours = nullptr;
    const glm::u8vec3 *faceColours = nullptr;  // 1 per triangle
    glm::u8vec3 flatColour{200, 200, 200};

    // Smooth shading with these (interpolated); without, each triangle's own normal (faceted).
    const glm::vec3 *vertexNormals = nullptr;

    // Wireframe: bit k of edgeMask[t] set = draw edge (corner k, corner k+1) of triangle t.
    // fanEdgeMask() gives the polygon edges of fan-triangulated polygons (no diagonals).
    const uint8_t *edgeMask = nullptr;
};

// Orbit camera around the bounding box of the framed positions.
struct Camera {
    float azimuthDeg = -35.0f;   // direction of the eye around +z; 0 = on the +x side
    float elevationDeg = 28.0f;  // above the horizontal plane
    float fovDeg = 30.0f;        // vertical field of view
    float margin = 0.05f;        // fraction of each side of the picture kept free around the model
};

struct View {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};  // includes the framing shift and zoom
    glm::vec3 eye{0.0f};
};

// Places the camera so the given points fill the picture (tight: their projected extent, centred,
// not the bounding sphere). Compute it once from one mesh and pass it to every render that must
// line up with it. With no finite point, frames the unit cube.
View fitView(const glm::vec3 *positions, size_t count, const Camera &camera, float aspect);

struct Lighting {
    // Direction towards the key light in camera space (x right, y up, z towards the viewer):
    // from above, left, in front, so the model's front and top read differently.
    glm::vec3 keyDirection{-0.45f, 0.65f, 0.62f};
    float ambient = 0.32f;
    float diffuse = 0.72f;
    float specular = 0.12f;  // white highlight, Blinn-Phong
    float shininess = 48.0f;
};

struct RenderOptions {
    int width = 640;
    int height = 640;
    int supersample = 3;  // samples per pixel side (1..4), box-filtered
    glm::u8vec3 background{232, 232, 228};
    Lighting lighting;
    glm::u8vec3 wireColour{25, 25, 30};
    float wireWidth = 1.0f;  // in output pixels
    float wireOpacity = 0.75f;
};

// Renders `mesh` as seen from `view`. Triangles with a vertex behind the eye are skipped (fitView
// never produces any).
Image renderMesh(const RenderMesh &mesh, const View &view, const RenderOptions &options = {});

// Edge masks for polygons fanned from their first vertex (attributes/triangulate.h): for a quad
// (a,b,c,d) -> (a,b,c), (a,c,d), the a-c diagonal is left out. One mask per fan triangle.
std::vector<uint8_t> fanEdgeMask(const uint32_t *polygonOffsets, size_t polygonCount);

// Images placed left to right on `background`, `gap` pixels apart, vertically centred.
Image sideBySide(const std::vector<Image> &images, int gap, glm::u8vec3 background);

}  // namespace voxelfair::render
