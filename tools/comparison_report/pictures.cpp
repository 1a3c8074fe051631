#include "comparison_report/pictures.h"

#include "render/mesh_renderer.h"
#include "render/png_writer.h"

#include <algorithm>
#include <cctype>

namespace fs = std::filesystem;

namespace voxelfair::report {

constexpr size_t kMaxWireframeQuads = 15000;

Pictures renderPictures(const ModelRun &run, const fs::path &folder, int size) {
    using namespace voxelfair::render;
    Pictures out;
    std::string stem = run.name;
    for (char &c : stem)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '-' && c != '_')
            c = '_';

    // One camera for every panel, framed on the raw voxels: a 3/4 view from above the front.
    const View view = fitView(run.raw.displayPositions.data(), run.raw.displayPositions.size(), Camera{}, 1.0f);
    RenderOptions options;
    options.width = options.height = size;

    auto meshOf = [](const Variant &v) {
        RenderMesh m;
        m.positions = v.displayPositions.data();
        m.vertexCount = v.displayPositions.size();
        m.triangles = v.attributes.triangles.data();
        m.triangleCount = v.attributes.triangleCount();
        m.faceColours = v.attributes.triangleColours.data();
        return m;
    };
    std::vector<Image> panels;
    auto add = [&](const Image &image, const std::string &suffix, const std::string &label) {
        const std::string file = stem + "_" + suffix + ".png";
        std::string error;
        if (!writePng((folder / file).string(), image.rgb.data(), image.width, image.height, 3, &error))
            std::fprintf(stderr, "%s\n", error.c_str());
        panels.push_back(image);
        out.files.push_back(file);
        out.labels.push_back(label);
    };

    // Geometry panels: crisp voxel colours and faceted shading, so only the shapes differ.
    add(renderMesh(meshOf(run.raw), view, options), "raw", "raw voxels");
    if (run.hasTaubin)
        add(renderMesh(meshOf(run.taubin), view, options), "taubin", "Taubin, 10 steps");
    add(renderMesh(meshOf(run.ours), view, options), "ours", "ours (paper, 1 pass)");
    if (run.hasConstrained)
        add(renderMesh(meshOf(run.constrained), view, options), "constrained", "constrained mode");
    if (run.hasOtherMeshLab) {
        add(renderMesh(meshOf(run.hc), view, options), "hc", "HC Laplacian");
        add(renderMesh(meshOf(run.twoStep), view, options), "twostep", "TwoStep");
    }
    if (run.hasVtk) {
        RenderMesh vtk;
        vtk.positions = run.vtk.displayPositions.data();
        vtk.vertexCount = run.vtk.displayPositions.size();
        vtk.triangles = run.vtk.triangles.data();
        vtk.triangleCount = run.vtk.triangles.size() / 3;
        add(renderMesh(vtk, view, options), "vtk", "VTK windowed sinc (no colours)");
    }
    // The product: the faired mesh with its smoothed normals and the baked texture.
    if (run.ours.hasAtlas) {
        RenderMesh textured = meshOf(run.ours);
        textured.vertexNormals = run.ours.displayNormals.data();
        textured.wedgeUv = run.ours.atlas.layout.wedgeUv.data();
        textured.texture = {run.ours.atlas.texture.width, run.ours.atlas.texture.height,
                            run.ours.atlas.texture.rgba.data()};
        add(renderMesh(textured, view, options), "textured", "ours + atlas texture, smooth normals");
        out.texture = stem + "_texture.png";
        const AtlasTexture &t = run.ours.atlas.texture;
        writePng((folder / out.texture).string(), t.rgba.data(), t.width, t.height, 4);
    }
    // The paper's Figure 9: the faired quads in wireframe, where the edges are not too dense to see.
    if (run.ours.mesh.quadCount() <= kMaxWireframeQuads) {
        const std::vector<uint8_t> quadEdges = fanEdgeMask(run.ours.mesh.offsets.data(), run.ours.mesh.quadCount());
        RenderMesh wire = meshOf(run.ours);
        wire.edgeMask = quadEdges.data();
        RenderOptions wireOptions = options;
        wireOptions.wireOpacity = 0.55f;
        out.wireframe = stem + "_ours_wire.png";
        const Image image = renderMesh(wire, view, wireOptions);
        writePng((folder / out.wireframe).string(), image.rgb.data(), image.width, image.height, 3);
    }
    const Image strip = sideBySide(panels, size / 40, options.background);
    out.strip = stem + "_strip.png";
    writePng((folder / out.strip).string(), strip.rgb.data(), strip.width, strip.height, 3);
    return out;
}

}  // namespace voxelfair::report
