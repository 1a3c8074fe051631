// Source faces by their place in the atlas; the contract is in uv_face_index.h.
#include "maps/uv_face_index.h"

#include "atlas/texel_raster.h"

#include <glm/geometric.hpp>

namespace voxelfair {

UvFaceGrid::UvFaceGrid(const SortedSource &sorted, int width, int height)
    : sorted_(sorted), width_(width), height_(height), cellsX_((width + kCell - 1) / kCell),
      cellsY_((height + kCell - 1) / kCell), box_(4 * sorted.mesh.faceCount) {
    // Each face's box in cells (clamped to the grid), and the faces reaching beyond their bucket's
    // neighbourhood. The sorted source's buckets are the same cells, row by row.
    const NormalBakeMesh &m = sorted.mesh;
    for (int by = 0; by < cellsY_; ++by)
        for (int bx = 0; bx < cellsX_; ++bx) {
            const size_t bucket = size_t(by) * size_t(cellsX_) + size_t(bx);
            for (uint32_t f = sorted.cellStart[bucket]; f < sorted.cellStart[bucket + 1]; ++f) {
                glm::dvec2 q[3];
                loadUv(m, f, width, height, q);
                const glm::dvec2 lo = glm::min(q[0], glm::min(q[1], q[2])), hi = glm::max(q[0], glm::max(q[1], q[2]));
                const int x0 = std::clamp(int(lo.x) / kCell, 0, cellsX_ - 1),
                          x1 = std::clamp(int(hi.x) / kCell, 0, cellsX_ - 1);
                const int y0 = std::clamp(int(lo.y) / kCell, 0, cellsY_ - 1),
                          y1 = std::clamp(int(hi.y) / kCell, 0, cellsY_ - 1);
                uint16_t *const box = &box_[4 * size_t(f)];
                box[0] = uint16_t(x0), box[1] = uint16_t(x1), box[2] = uint16_t(y0), box[3] = uint16_t(y1);
                if (x0 < bx - kReach || x1 > bx + kReach || y0 < by - kReach || y1 > by + kReach)
                    wide_.push_back(f);
            }
        }
}

uint32_t UvFaceGrid::find(glm::dvec2 p) const {
    const int cx = std::clamp(int(p.x) / kCell, 0, cellsX_ - 1), cy = std::clamp(int(p.y) / kCell, 0, cellsY_ - 1);
    auto meets = [&](uint32_t f) {
        const uint16_t *const box = &box_[4 * size_t(f)];
        return box[0] <= cx && cx <= box[1] && box[2] <= cy && cy <= box[3];
    };
    // The faces whose box meets the cell, in face order: those of the buckets around it (not
    // wide), and the wide ones.
    std::vector<uint32_t> faces;
    for (int by = std::max(cy - kReach, 0); by <= std::min(cy + kReach, cellsY_ - 1); ++by)
        for (int bx = std::max(cx - kReach, 0); bx <= std::min(cx + kReach, cellsX_ - 1); ++bx) {
            const size_t bucket = size_t(by) * size_t(cellsX_) + size_t(bx);
            for (uint32_t f = sorted_.cellStart[bucket]; f < sorted_.cellStart[bucket + 1]; ++f) {
                const uint16_t *const box = &box_[4 * size_t(f)];
                const bool wide =
                    box[0] < bx - kReach || box[1] > bx + kReach || box[2] < by - kReach || box[3] > by + kReach;
                if (!wide && meets(f))
                    faces.push_back(f);
            }
        }
    for (const uint32_t f : wide_)
        if (meets(f))
            faces.push_back(f);
    std::sort(faces.begin(), faces.end());
    uint32_t nearest = UINT32_MAX;
    double best = 0;
    glm::dvec2 q[3];
    for (const uint32_t f : faces) {
        loadUv(sorted_.mesh, f, width_, height_, q);
        const double d = doubleArea(q[0], q[1], q[2]);
        const double a = doubleArea(p, q[1], q[2]) / d, b = doubleArea(q[0], p, q[2]) / d;
        if (d != 0 && a >= 0 && b >= 0 && a + b <= 1)
            return f;
        const glm::dvec2 centroid = (q[0] + q[1] + q[2]) / 3.0;
        const double distance = glm::dot(centroid - p, centroid - p);
        if (nearest == UINT32_MAX || distance < best)
            nearest = f, best = distance;
    }
    return nearest;
}

FaceBands faceBands(const NormalBakeMesh &mesh, int width, int height, int bandRows) {
    const size_t bands = size_t((height + bandRows - 1) / bandRows);
    FaceBands out;
    out.start.assign(bands + 1, 0);
    // Each face's bands [first, last] (first > last: none) and its UV box's left texel, once.
    std::vector<uint32_t> first(mesh.faceCount), last(mesh.faceCount), column(size_t(width) + 2, 0);
    std::vector<uint32_t> left(mesh.faceCount);
    // A row's band (rows are not negative): a shift for the bands of a power of two of rows (32,
    // the bake's), instead of a division a face twice.
    int shift = -1;
    for (int s = 0; s < 31; ++s)
        if (bandRows == 1 << s)
            shift = s;
    auto bandOf = [&](int row) { return uint32_t(shift >= 0 ? row >> shift : row / bandRows); };
    for (size_t f = 0; f < mesh.faceCount; ++f) {
        glm::dvec2 q[3];
        loadUv(mesh, f, width, height, q);
        const double lo = std::min({q[0].y, q[1].y, q[2].y}), hi = std::max({q[0].y, q[1].y, q[2].y});
        if (!std::isfinite(lo) || !std::isfinite(hi) || hi < -1 || lo > height + 1) {
            first[f] = 1, last[f] = 0;
            continue;
        }
        first[f] = bandOf(std::clamp(int(std::floor(lo)) - 1, 0, height - 1));
        last[f] = bandOf(std::clamp(int(std::ceil(hi)) + 1, 0, height - 1));
        for (uint32_t b = first[f]; b <= last[f]; ++b)
            ++out.start[b + 1];
        const glm::vec2 *uv = &mesh.wedgeUv[3 * f];
        const float x = std::min({uv[0].x, uv[1].x, uv[2].x}) * float(width);
        left[f] = std::isfinite(x) ? uint32_t(std::clamp(x, 0.0f, float(width))) : 0;
        ++column[left[f] + 1];
    }
    for (size_t b = 0; b < bands; ++b)
        out.start[b + 1] += out.start[b];
    // Each band's faces from left to right (by their UV boxes' left texel, then index): a band
    // sweeps its rows once, its texels and the source faces under them stay in cache. One stable
    // counting sort of all faces on the left texel, then the faces dealt to their bands in that
    // order: within a band, faces of the same column stay in index order.
    for (size_t c = 1; c < column.size(); ++c)
        column[c] += column[c - 1];
    std::vector<uint32_t> sorted(column.back());
    for (size_t f = 0; f < mesh.faceCount; ++f)
        if (first[f] <= last[f])
            sorted[column[left[f]]++] = uint32_t(f);
    out.faces.resize(out.start.back());
    std::vector<uint32_t> fill(out.start.begin(), out.start.end() - 1);
    for (const uint32_t f : sorted)
        for (uint32_t b = first[f]; b <= last[f]; ++b)
            out.faces[fill[b]++] = f;
    return out;
}

SortedSource::SortedSource(const NormalBakeMesh &source, int width, int height)
    : triangles(3 * source.faceCount), wedgeUv(3 * source.faceCount), cellsX((width + kSortCell - 1) / kSortCell),
      cellsY((height + kSortCell - 1) / kSortCell), cellStart(size_t(cellsX) * size_t(cellsY) + 1, 0), mesh(source) {
    std::vector<uint32_t> cellOf(source.faceCount);
    for (size_t f = 0; f < source.faceCount; ++f) {
        const glm::vec2 *uv = &source.wedgeUv[3 * f];
        const glm::vec2 c = (uv[0] + uv[1] + uv[2]) / 3.0f;
        cellOf[f] = cell(double(c.x) * width, double(c.y) * height);
        ++cellStart[cellOf[f] + 1];
    }
    for (size_t c = 1; c < cellStart.size(); ++c)
        cellStart[c] += cellStart[c - 1];
    std::vector<uint32_t> fill(cellStart.begin(), cellStart.end() - 1);
    sortedFace.resize(source.faceCount);
    for (size_t f = 0; f < source.faceCount; ++f) {
        const size_t to = fill[cellOf[f]]++;
        sortedFace[f] = uint32_t(to);
        for (int k = 0; k < 3; ++k) {
            triangles[3 * to + size_t(k)] = source.triangles[3 * f + size_t(k)];
            wedgeUv[3 * to + size_t(k)] = source.wedgeUv[3 * f + size_t(k)];
        }
    }
    mesh.triangles = triangles.data();
    mesh.wedgeUv = wedgeUv.data();
}

}  // namespace voxelfair
