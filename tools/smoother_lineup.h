// The smoothers users compare, beside ours, for tools/comparison_report: MeshLab's HC Laplacian and
// TwoStep Smooth as MeshLab runs them (testkit/smoothers/vcg_smoothers.h), VTK's discrete marching
// cubes + windowed sinc on every part of a model (testkit/smoothers/vtk_windowed_sinc.h), and the
// report's section on the shape families of testkit/shapes/shape_families.h: one table (worst RMS
// per family and method) and one picture strip per family (raw voxels, VTK, the paper's pass, the
// constrained mode), so a reader sees flat faces, fillets and edges.
#pragma once

#include "pipeline/pipeline_stages.h"
#include "render/mesh_renderer.h"
#include "render/png_writer.h"

#include "smoothers/smoothing_comparison.h"
#include "shapes/shape_families.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat4x4.hpp>

namespace voxelfair::lineup {

// A triangle mesh of its own connectivity (VTK's), in model space for pictures.
struct TriangleSurface {
    std::vector<glm::vec3> positions;  // the chain's coordinates (each part's voxel units)
    std::vector<glm::vec3> displayPositions;
    std::vector<uint32_t> triangles;
};

#ifdef VOXELFAIR_HAVE_VTK
// VTK on each part's volume, placed like the chain's surface (part.toModel) and, for pictures,
// in model space (model.toDisplay).
inline TriangleSurface vtkSurface(const pipeline::Model &model) {
    TriangleSurface out;
    for (size_t part = 0; part < model.scene.parts.size(); ++part) {
        const PlacedVolume &p = model.scene.parts[part];
        const vtksinc::TriangleMesh mesh = vtksinc::smoothLikeVtk(*p.volume);
        const uint32_t base = uint32_t(out.positions.size());
        const bool mirrored = glm::determinant(glm::mat3(p.toModel)) < 0.0f;
        for (const glm::vec3 &v : mesh.positions) {
            const glm::vec3 x = glm::vec3(p.toModel * glm::vec4(v, 1.0f));
            out.positions.push_back(x);
            out.displayPositions.push_back(glm::vec3(model.toDisplay[part] * glm::vec4(x, 1.0f)));
        }
        for (size_t t = 0; t + 2 < mesh.triangles.size(); t += 3)
            for (int k : {0, mirrored ? 2 : 1, mirrored ? 1 : 2})
                out.triangles.push_back(base + mesh.triangles[t + size_t(k)]);
    }
    return out;
}
#endif

// Worst RMS and worst |volume change| per family and method, over `instances` shapes of each
// family of shape_families.h (samples per mesh: `samples`), as a markdown table; the best
// smoothed value of each row in bold.
inline std::string familyTable(int instances, size_t samples) {
    comparison::Options options;
    options.samples = samples;
    struct Summary {
        double worst = 0.0, worstVolume = 0.0;
    };
    std::map<std::pair<std::string, std::string>, Summary> summary;
    std::vector<std::string> methods, families;
    for (const shapes::FamilyShape &f : shapes::familyShapes(instances)) {
        if (std::find(families.begin(), families.end(), f.family) == families.end())
            families.push_back(f.family);
        for (const comparison::Row &row : comparison::compare(f.shape, options)) {
            Summary &s = summary[{f.family, row.method}];
            s.worst = std::max(s.worst, row.error.rms);
            s.worstVolume = std::max(s.worstVolume, std::fabs(row.error.volumeChangePercent));
            if (std::find(methods.begin(), methods.end(), row.method) == methods.end())
                methods.push_back(row.method);
        }
    }
    std::ostringstream md;
    md << "| family |";
    for (const std::string &m : methods)
        md << " " << m << " |";
    md << "\n|---|";
    for (size_t i = 0; i < methods.size(); ++i)
        md << "---:|";
    md << "\n";
    char cell[64];
    for (const std::string &family : families) {
        double best = 1e30;
        for (const std::string &m : methods)
            if (m != comparison::kRawMethod)
                best = std::min(best, summary[{family, m}].worst);
        md << "| " << family << " |";
        for (const std::string &m : methods) {
            const Summary &s = summary[{family, m}];
            const bool bold = m != comparison::kRawMethod && s.worst == best;
            std::snprintf(cell, sizeof cell, " %s%.3f%s (%.1f%%) |", bold ? "**" : "", s.worst, bold ? "**" : "",
                          s.worstVolume);
            md << cell;
        }
        md << "\n";
    }
    return md.str();
}

// One strip per family (its first instance): raw voxels, VTK (when built with it), the paper's
// pass, the constrained mode; same camera, faceted shading. Returns the report's markdown.
inline std::string familyPictures(const std::filesystem::path &folder, int size) {
    using namespace voxelfair::render;
    std::ostringstream md;
    std::vector<std::string> seen;
    for (const shapes::FamilyShape &f : shapes::familyShapes(1)) {
        if (std::find(seen.begin(), seen.end(), f.family) != seen.end())
            continue;
        seen.push_back(f.family);
        const VoxelVolume volume = shapes::voxelize(f.shape);
        const BoundarySurface surface = extractBoundarySurface(volume);
        const comparison::QuadFan fan = comparison::quadFan(surface);
        const std::vector<uint32_t> &offsets = fan.offsets, &triangles = fan.triangles;
        std::vector<std::pair<std::string, std::pair<std::vector<glm::vec3>, std::vector<uint32_t>>>> panels;
        panels.push_back({"raw voxels", {surface.positions, triangles}});
#ifdef VOXELFAIR_HAVE_VTK
        const vtksinc::TriangleMesh vtk = vtksinc::smoothLikeVtk(volume);
        panels.push_back({"VTK windowed sinc", {vtk.positions, vtk.triangles}});
#endif
        std::vector<glm::vec3> paper = surface.positions, ours = surface.positions;
        fairModifiedLanczos({paper.data(), paper.size(), offsets.data(), surface.quads.data(), surface.quadCount()},
                            nullptr);
        fairConstrained({ours.data(), ours.size(), offsets.data(), surface.quads.data(), surface.quadCount()}, nullptr);
        panels.push_back({"paper, 1 pass", {paper, triangles}});
        panels.push_back({"constrained", {ours, triangles}});

        Camera camera;
        camera.elevationDeg = 30.0f;
        const View view = fitView(surface.positions.data(), surface.positions.size(), camera, 1.0f);
        RenderOptions options;
        options.width = options.height = size;
        std::vector<Image> images;
        for (const auto &[label, mesh] : panels) {
            RenderMesh m;
            m.positions = mesh.first.data();
            m.vertexCount = mesh.first.size();
            m.triangles = mesh.second.data();
            m.triangleCount = mesh.second.size() / 3;
            m.flatColour = glm::u8vec3(190, 196, 204);
            images.push_back(renderMesh(m, view, options));
        }
        std::string stem = "family_" + f.family;
        for (char &c : stem)
            if (!std::isalnum(static_cast<unsigned char>(c)))
                c = '_';
        const Image strip = sideBySide(images, size / 40, options.background);
        writePng((folder / (stem + ".png")).string(), strip.rgb.data(), strip.width, strip.height, 3);
        md << "**" << f.family << "** (" << f.shape.name << "): ";
        for (size_t i = 0; i < panels.size(); ++i)
            md << (i ? ", " : "") << panels[i].first;
        md << ".\n\n![" << f.family << "](" << stem << ".png)\n\n";
    }
    return md.str();
}

}  // namespace voxelfair::lineup
