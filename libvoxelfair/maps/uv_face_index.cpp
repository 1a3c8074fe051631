// Source faces by their place in the atlas; the contract is in uv_face_index.h.
#include "maps/uv_face_index.h"

#include "atlas/texel_raster.h"

#include <glm/geometric.hpp>

namespace voxelfair {

UvFaceGrid::UvFaceGrid(const NormalBakeMesh &m, int width, int height)
    : mesh_(m), width_(width), height_(height), cellsX_((width + kCell - 1) / kCell),
      cellsY_((height + kCell - 1) / kCell) {
    start_.assign(size_t(cellsX_) * size_t(cellsY_) + 1, 0);
    auto forCells = [&](size_t f, auto &&visit) {
        glm::dvec2 q[3];
        loadUv(m, f, width, height, q);
        const glm::dvec2 lo = glm::min(q[0], glm::min(q[1], q[2])), hi = glm::max(q[0], glm::max(q[1], q[2]));
        const int x0 = std::clamp(int(lo.x) / kCell, 0, cellsX_ - 1),
                  x1 = std::clamp(int(hi.x) / kCell, 0, cellsX_ - 1);
        const int y0 = std::clamp(int(lo.y) / kCell, 0, cellsY_ - 1),
                  y1 = std::clamp(int(hi.y) / kCell, 0, cellsY_ - 1);
        for (int y = y0; y <= y1; ++y)
            for (int x = x0; x <= x1; ++x)
                visit(size_t(y) * size_t(cellsX_) + size_t(x));
    };
    for (size_t f = 0; f < m.faceCount; ++f)
        forCells(f, [&](size_t c) { ++start_[c + 1]; });
    for (size_t c = 1; c < start_.size(); ++c)
        start_[c] += start_[c - 1];
    faces_.resize(start_.back());
    std::vector<uint32_t> fill(start_.begin(), start_.end() - 1);
    for (size_t f = 0; f < m.faceCount; ++f)
        forCells(f, [&](size_t c) { faces_[fill[c]++] = uint32_t(f); });
}

uint32_t UvFaceGrid::find(glm::dvec2 p) const {
    const int cx = std::clamp(int(p.x) / kCell, 0, cellsX_ - 1), cy = std::clamp(int(p.y) / kCell, 0, cellsY_ - 1);
    const size_t c = size_t(cy) * size_t(cellsX_) + size_t(cx);
    uint32_t nearest = UINT32_MAX;
    double best = 0;
    glm::dvec2 q[3];
    for (uint32_t i = start_[c]; i < start_[c + 1]; ++i) {
        loadUv(mesh_, faces_[i], width_, height_, q);
        const double d = doubleArea(q[0], q[1], q[2]);
        const double a = doubleArea(p, q[1], q[2]) / d, b = doubleArea(q[0], p, q[2]) / d;
        if (d != 0 && a >= 0 && b >= 0 && a + b <= 1)
            return faces_[i];
        const glm::dvec2 centroid = (q[0] + q[1] + q[2]) / 3.0;
        const double distance = glm::dot(centroid - p, centroid - p);
        if (nearest == UINT32_MAX || distance < best)
            nearest = faces_[i], best = distance;
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
    for (size_t f = 0; f < mesh.faceCount; ++f) {
        glm::dvec2 q[3];
        loadUv(mesh, f, width, height, q);
        const double lo = std::min({q[0].y, q[1].y, q[2].y}), hi = std::max({q[0].y, q[1].y, q[2].y});
        if (!std::isfinite(lo) || !std::isfinite(hi) || hi < -1 || lo > height + 1) {
            first[f] = 1, last[f] = 0;
            continue;
        }
        first[f] = uint32_t(std::clamp(int(std::floor(lo)) - 1, 0, height - 1) / bandRows);
        last[f] = uint32_t(std::clamp(int(std::ceil(hi)) + 1, 0, height - 1) / bandRows);
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
