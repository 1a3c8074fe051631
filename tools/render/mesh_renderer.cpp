#include "render/mesh_renderer.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec4.hpp>

namespace voxelfair::render {

namespace {

constexpr float kPi = 3.14159265358979f;

glm::vec3 eyeDirection(const Camera &camera) {
    const float az = camera.azimuthDeg * kPi / 180.0f, el = camera.elevationDeg * kPi / 180.0f;
    return {std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)};
}

bool finite(const glm::vec3 &p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

glm::vec3 toFloat(glm::u8vec3 c) { return glm::vec3(c); }

// Bilinear, clamped to the edge texels; texel centres sit at half-integer texel coordinates.
glm::vec3 sampleBilinear(const Texture &t, glm::vec2 uv) {
    const float x = glm::clamp(uv.x * float(t.width) - 0.5f, 0.0f, float(t.width - 1));
    const float y = glm::clamp((1.0f - uv.y) * float(t.height) - 0.5f, 0.0f, float(t.height - 1));
    const int x0 = int(x), y0 = int(y);
    const int x1 = std::min(x0 + 1, t.width - 1), y1 = std::min(y0 + 1, t.height - 1);
    const float fx = x - float(x0), fy = y - float(y0);
    auto texel = [&t](int tx, int ty) {
        const uint8_t *p = t.rgba + (size_t(ty) * size_t(t.width) + size_t(tx)) * 4;
        return glm::vec3(p[0], p[1], p[2]);
    };
    return glm::mix(glm::mix(texel(x0, y0), texel(x1, y0), fx), glm::mix(texel(x0, y1), texel(x1, y1), fx), fy);
}

// A vertex after projection: supersampled screen position (y down), NDC depth, 1/w, and its
// camera-space position for lighting.
struct ScreenVertex {
    glm::vec2 xy{0.0f};
    float depth = 0.0f;
    float invW = 0.0f;
    glm::vec3 camera{0.0f};
    bool valid = false;
};

float edgeFunction(glm::vec2 a, glm::vec2 b, glm::vec2 p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

}  // namespace

View fitView(const glm::vec3 *positions, size_t count, const Camera &camera, float aspect) {
    glm::vec3 lo(std::numeric_limits<float>::max()), hi(-std::numeric_limits<float>::max());
    for (size_t i = 0; i < count; ++i)
        if (finite(positions[i])) {
            lo = glm::min(lo, positions[i]);
            hi = glm::max(hi, positions[i]);
        }
    if (lo.x > hi.x)
        lo = glm::vec3(0.0f), hi = glm::vec3(1.0f);
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
    const float fov = glm::radians(glm::clamp(camera.fovDeg, 1.0f, 150.0f));

    // Far enough that the bounding sphere fits; the exact framing is done below in NDC.
    const float distance = radius / std::sin(0.5f * fov * std::min(aspect, 1.0f)) * 1.05f;
    View v;
    v.eye = centre + distance * eyeDirection(camera);
    // Looking straight down (elevation +-90) the up vector would be parallel to the view.
    const glm::vec3 up = std::fabs(camera.elevationDeg) > 89.0f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
    v.view = glm::lookAt(v.eye, centre, up);
    const float zNear = std::max(distance - 1.01f * radius, 1e-3f * distance);
    const float zFar = distance + 1.01f * radius;
    const glm::mat4 projection = glm::perspective(fov, aspect, zNear, zFar);

    // Projected extent of the points, then a zoom and shift in clip space (a lens shift: the
    // perspective is unchanged) that centres it with the requested margin.
    glm::vec2 ndcLo(std::numeric_limits<float>::max()), ndcHi(-std::numeric_limits<float>::max());
    const glm::mat4 viewProjection = projection * v.view;
    for (size_t i = 0; i < count; ++i) {
        if (!finite(positions[i]))
            continue;
        const glm::vec4 clip = viewProjection * glm::vec4(positions[i], 1.0f);
        const glm::vec2 ndc = glm::vec2(clip) / clip.w;
        ndcLo = glm::min(ndcLo, ndc);
        ndcHi = glm::max(ndcHi, ndc);
    }
    glm::mat4 frame(1.0f);
    if (ndcLo.x <= ndcHi.x) {
        const glm::vec2 extent = glm::max(ndcHi - ndcLo, glm::vec2(1e-6f));
        const glm::vec2 mid = 0.5f * (ndcLo + ndcHi);
        // NDC spans each side of the picture, so one margin fraction serves both axes.
        const float room = 2.0f * (1.0f - 2.0f * glm::clamp(camera.margin, 0.0f, 0.45f));
        const float s = std::min(room / extent.x, room / extent.y);
        frame[0][0] = s;
        frame[1][1] = s;
        frame[3][0] = -s * mid.x;
        frame[3][1] = -s * mid.y;
    }
    v.projection = frame * projection;
    return v;
}

Image renderMesh(const RenderMesh &mesh, const View &view, const RenderOptions &options) {
    const int ss = glm::clamp(options.supersample, 1, 4);
    const int width = std::max(options.width, 1), height = std::max(options.height, 1);
    const int W = width * ss, H = height * ss;

    std::vector<float> depth(size_t(W) * size_t(H), std::numeric_limits<float>::infinity());
    std::vector<uint8_t> colour(size_t(W) * size_t(H) * 3);
    for (size_t i = 0; i < depth.size(); ++i)
        for (int c = 0; c < 3; ++c)
            colour[3 * i + size_t(c)] = options.background[c];

    const glm::mat4 viewProjection = view.projection * view.view;
    const glm::mat3 normalToCamera(view.view);  // the view is a rigid motion
    std::vector<ScreenVertex> screen(mesh.vertexCount);
    for (size_t i = 0; i < mesh.vertexCount; ++i) {
        const glm::vec3 &p = mesh.positions[i];
        const glm::vec4 clip = viewProjection * glm::vec4(p, 1.0f);
        ScreenVertex &s = screen[i];
        s.valid = finite(p) && clip.w > 1e-6f;
        if (!s.valid)
            continue;
        s.invW = 1.0f / clip.w;
        s.xy = {(clip.x * s.invW * 0.5f + 0.5f) * float(W), (0.5f - clip.y * s.invW * 0.5f) * float(H)};
        s.depth = clip.z * s.invW;
        s.camera = glm::vec3(view.view * glm::vec4(p, 1.0f));
    }

    const Lighting &light = options.lighting;
    const glm::vec3 toLight = glm::normalize(light.keyDirection);
    const glm::vec3 wire = toFloat(options.wireColour);
    const float wireHalf = 0.5f * options.wireWidth * float(ss);
    const bool textured = mesh.wedgeUv && mesh.texture.rgba && mesh.texture.width > 0 && mesh.texture.height > 0;

    for (size_t t = 0; t < mesh.triangleCount; ++t) {
        const uint32_t idx[3] = {mesh.triangles[3 * t], mesh.triangles[3 * t + 1], mesh.triangles[3 * t + 2]};
        if (idx[0] >= mesh.vertexCount || idx[1] >= mesh.vertexCount || idx[2] >= mesh.vertexCount)
            continue;
        const ScreenVertex *v[3] = {&screen[idx[0]], &screen[idx[1]], &screen[idx[2]]};
        if (!v[0]->valid || !v[1]->valid || !v[2]->valid)
            continue;
        const float area = edgeFunction(v[0]->xy, v[1]->xy, v[2]->xy);
        if (area == 0.0f || !std::isfinite(area))
            continue;
        // Counter-clockwise seen from the eye is clockwise on a y-down screen: negative area.
        const float facing = area < 0.0f ? 1.0f : -1.0f;
        glm::vec3 faceNormal = glm::cross(v[1]->camera - v[0]->camera, v[2]->camera - v[0]->camera);
        const float faceNormalLength = glm::length(faceNormal);
        faceNormal = faceNormalLength > 0.0f ? faceNormal / faceNormalLength : glm::vec3(0, 0, 1);
        // Two-sided: a back face is lit as seen from the front. The face normal then points
        // towards the eye, whatever the winding.
        if (glm::dot(faceNormal, -v[0]->camera) < 0.0f)
            faceNormal = -faceNormal;

        glm::vec3 cornerNormal[3] = {};
        if (mesh.vertexNormals)
            for (int k = 0; k < 3; ++k)
                cornerNormal[k] = facing * (normalToCamera * mesh.vertexNormals[idx[k]]);
        float edgeLength[3];
        for (int k = 0; k < 3; ++k)
            edgeLength[k] = glm::length(v[(k + 1) % 3]->xy - v[k]->xy);
        const uint8_t edges = mesh.edgeMask ? mesh.edgeMask[t] : 0;
        auto edgeOf = [&](int i, int j, glm::vec2 p) {
            return idx[i] < idx[j] ? edgeFunction(v[i]->xy, v[j]->xy, p) : -edgeFunction(v[j]->xy, v[i]->xy, p);
        };

        const glm::vec2 lo = glm::min(v[0]->xy, glm::min(v[1]->xy, v[2]->xy));
        const glm::vec2 hi = glm::max(v[0]->xy, glm::max(v[1]->xy, v[2]->xy));
        const int x0 = std::max(0, int(std::floor(lo.x))), x1 = std::min(W - 1, int(std::ceil(hi.x)));
        const int y0 = std::max(0, int(std::floor(lo.y))), y1 = std::min(H - 1, int(std::ceil(hi.y)));
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x) {
                const glm::vec2 p(float(x) + 0.5f, float(y) + 0.5f);
                // Screen-space barycentrics. Each edge is evaluated from its lower vertex index, so
                // the two triangles of a shared edge get exactly opposite values: no pinholes.
                const float b[3] = {edgeOf(1, 2, p) / area, edgeOf(2, 0, p) / area, edgeOf(0, 1, p) / area};
                if (b[0] < 0.0f || b[1] < 0.0f || b[2] < 0.0f)
                    continue;
                const float z = b[0] * v[0]->depth + b[1] * v[1]->depth + b[2] * v[2]->depth;
                const size_t at = size_t(y) * size_t(W) + size_t(x);
                if (!(z < depth[at]) || z < -1.0f)
                    continue;
                depth[at] = z;

                // Perspective-correct weights for the attributes.
                float q[3] = {b[0] * v[0]->invW, b[1] * v[1]->invW, b[2] * v[2]->invW};
                const float qSum = q[0] + q[1] + q[2];
                for (float &qi : q)
                    qi /= qSum;

                glm::vec3 albedo;
                if (textured) {
                    const glm::vec2 *uv = mesh.wedgeUv + 3 * t;
                    albedo = sampleBilinear(mesh.texture, q[0] * uv[0] + q[1] * uv[1] + q[2] * uv[2]);
                } else if (mesh.vertexColours) {
                    albedo = q[0] * toFloat(mesh.vertexColours[idx[0]]) + q[1] * toFloat(mesh.vertexColours[idx[1]]) +
                             q[2] * toFloat(mesh.vertexColours[idx[2]]);
                } else if (mesh.faceColours) {
                    albedo = toFloat(mesh.faceColours[t]);
                } else {
                    albedo = toFloat(mesh.flatColour);
                }

                glm::vec3 n = faceNormal;
                if (mesh.vertexNormals) {
                    const glm::vec3 s = q[0] * cornerNormal[0] + q[1] * cornerNormal[1] + q[2] * cornerNormal[2];
                    const float sl = glm::length(s);
                    if (sl > 1e-6f)
                        n = s / sl;
                }
                const glm::vec3 toEye =
                    glm::normalize(-(q[0] * v[0]->camera + q[1] * v[1]->camera + q[2] * v[2]->camera));
                const float lambert = std::max(0.0f, glm::dot(n, toLight));
                const glm::vec3 halfway = glm::normalize(toLight + toEye);
                const float highlight =
                    lambert > 0.0f ? light.specular * std::pow(std::max(0.0f, glm::dot(n, halfway)), light.shininess)
                                   : 0.0f;
                glm::vec3 shaded = albedo * (light.ambient + light.diffuse * lambert) + glm::vec3(255.0f * highlight);

                if (edges) {
                    // Distance in samples to each drawn edge: edge k is opposite corner k + 2.
                    for (int k = 0; k < 3; ++k)
                        if ((edges >> k) & 1) {
                            const float distance = b[(k + 2) % 3] * std::fabs(area) / std::max(edgeLength[k], 1e-6f);
                            if (distance < wireHalf) {
                                shaded = glm::mix(shaded, wire, options.wireOpacity);
                                break;
                            }
                        }
                }
                for (int c = 0; c < 3; ++c)
                    colour[3 * at + size_t(c)] = uint8_t(glm::clamp(shaded[c] + 0.5f, 0.0f, 255.0f));
            }
    }

    // Box filter down to the output size.
    Image image;
    image.width = width;
    image.height = height;
    image.rgb.resize(size_t(width) * size_t(height) * 3);
    const int samples = ss * ss;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            for (int c = 0; c < 3; ++c) {
                int sum = 0;
                for (int sy = 0; sy < ss; ++sy)
                    for (int sx = 0; sx < ss; ++sx)
                        sum += colour[(size_t(y * ss + sy) * size_t(W) + size_t(x * ss + sx)) * 3 + size_t(c)];
                image.rgb[(size_t(y) * size_t(width) + size_t(x)) * 3 + size_t(c)] =
                    uint8_t((sum + samples / 2) / samples);
            }
    return image;
}

std::vector<uint8_t> fanEdgeMask(const uint32_t *polygonOffsets, size_t polygonCount) {
    std::vector<uint8_t> masks;
    for (size_t p = 0; p < polygonCount; ++p) {
        const uint32_t n = polygonOffsets[p + 1] - polygonOffsets[p];
        // Fan triangle j is (v0, v[j+1], v[j+2]): its edge 1 is always a polygon edge, edge 0
        // only for the first triangle, edge 2 only for the last.
        for (uint32_t j = 0; n >= 3 && j + 2 < n; ++j)
            masks.push_back(uint8_t(2 | (j == 0 ? 1 : 0) | (j + 3 == n ? 4 : 0)));
    }
    return masks;
}

Image sideBySide(const std::vector<Image> &images, int gap, glm::u8vec3 background) {
    Image out;
    for (const Image &image : images) {
        out.width += image.width;
        out.height = std::max(out.height, image.height);
    }
    if (images.empty())
        return out;
    out.width += gap * int(images.size() - 1);
    out.rgb.resize(size_t(out.width) * size_t(out.height) * 3);
    for (size_t i = 0; i < out.rgb.size(); i += 3)
        for (int c = 0; c < 3; ++c)
            out.rgb[i + size_t(c)] = background[c];
    int left = 0;
    for (const Image &image : images) {
        const int top = (out.height - image.height) / 2;
        for (int y = 0; y < image.height; ++y)
            std::copy_n(&image.rgb[size_t(y) * size_t(image.width) * 3], size_t(image.width) * 3,
                        &out.rgb[(size_t(top + y) * size_t(out.width) + size_t(left)) * 3]);
        left += image.width + gap;
    }
    return out;
}

}  // namespace voxelfair::render
