#include "comparison_report/sections.h"

#include "checks/surface_error.h"
#include "comparison_report/tables.h"
#include "smoothers/smoothing_comparison.h"
#include "smoother_lineup.h"

#include <algorithm>
#include <fstream>
#include <thread>

#include <glm/geometric.hpp>

namespace voxelfair::report {

std::string machine() {
    std::ifstream cpuinfo("/proc/cpuinfo");
    std::string line, cpu = "unknown CPU";
    while (std::getline(cpuinfo, line))
        if (line.rfind("model name", 0) == 0) {
            cpu = line.substr(line.find(':') + 2);
            break;
        }
    // Other work on the machine slows the timings down: say how busy it was.
    std::string load = "?";
    std::ifstream("/proc/loadavg") >> load;
    return cpu + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads, load average " + load;
}

void writeIntroduction(std::ostream &out, const std::vector<std::string> &skipped) {
    out << "# voxelfair comparison report\n\n"
        << "Our chain (paper sections 4.2-4.5: extraction, one pass of the modified-Lanczos fairing, attribute "
           "smoothing, texture atlas) against MeshLab 2020.09's Taubin Smooth (vcglib, 10 steps, lambda 0.5, "
           "mu -0.53, on the a-c triangulation MeshLab holds).\n\n"
        << "Machine: " << machine() << ". Times: best of " << kRepeats
        << " runs in one process, one thread, Release build. Distances in voxels.\n\n";
#ifndef VOXELFAIR_HAVE_VCGLIB
    out << "Built without vcglib: no Taubin columns.\n\n";
#endif
#ifndef VOXELFAIR_HAVE_VTK
    out << "Built without VTK: no VTK columns.\n\n";
#endif
    if (!skipped.empty()) {
        out << "Not shown: ";
        for (size_t i = 0; i < skipped.size(); ++i)
            out << (i ? ", " : "") << skipped[i];
        out << ".\n\n";
    }
}

void writeFidelity(std::ostream &out, const std::vector<ModelRun> &runs) {
    // Fidelity on analytic shapes.
    out << "## Fidelity to the true surface (voxelized analytic shapes)\n\n"
        << "Distances from 200k area-uniform samples of each triangulated mesh to the shape's exact SDF "
           "(testkit/smoothers/smoothing_comparison.h). Bias > 0: the mesh lies outside on average. Volume: "
           "enclosed volume against the true solid's.\n\n";
    Table fidelity{{"shape", "method", "RMS", "max", "bias", "volume %"}, {}, 2};
    for (const ModelRun &run : runs) {
        if (!run.shape)
            continue;
        // Every smoother the comparison knows (the second mode included, once it exists).
        for (const comparison::Row &r : comparison::compare(*run.shape))
            fidelity.rows.push_back({r.shape, r.method, format("%.4f", r.error.rms), format("%.4f", r.error.max),
                                     format("%+.4f", r.error.bias), format("%+.2f", r.error.volumeChangePercent)});
    }
    out << fidelity.markdown() << "\n";
}

void writeTimes(std::ostream &out, const std::vector<ModelRun> &runs) {
    // Table 1: time per stage.
    out << "## Time per stage (the paper's Table 1)\n\n"
        << "Milliseconds. Extraction: section 4.2 over every part (VXL sections in their own voxel units, as the "
           "authors ran them; their HVA placement is applied only for the pictures). Fairing: one pass, adjacency "
           "included. Attributes: face and vertex normals, vertex colours, quads to triangles. Atlas: charts, "
           "packing and the baked texture (4 texels per voxel edge). Taubin: the filter body on vcglib's mesh "
           "(building that mesh, which MeshLab already holds, is the last column).\n\n";
    out << "The paper's Table 1 (ms; HP TX1120 tablet, dual-core 1.8 GHz, 2010):\n\n"
        << Table{{"model", "opaque voxels", "extraction", "fairing", "attributes", "atlas", "Taubin"},
                 {{"Demo Truck", "7893", "35", "11", "14", "316", "47"},
                  {"Kirov", "35841", "397", "52", "56", "1237", "203"},
                  {"Yuri Head", "42733", "327", "124", "131", "5522", "485"},
                  {"Warhammer", "63150", "359", "186", "201", "6393", "735"}}}
               .markdown()
        << "\nOurs:\n\n";
    Table times{{"model", "opaque voxels", "extraction", "fairing", "attributes", "atlas", "ours total"}, {}};
    if (!runs.empty() && runs.front().hasConstrained)
        times.header.push_back("constrained fairing");
    if (!runs.empty() && runs.front().hasTaubin)
        for (const char *h : {"Taubin 10", "Taubin chain total", "vcg mesh build"})
            times.header.push_back(h);
    for (const ModelRun &r : runs) {
        const double total = r.extractMs + r.ours.smoothMs + r.ours.attributesMs + r.ours.atlasMs;
        std::vector<std::string> row = {r.name,
                                        std::to_string(r.solidVoxels),
                                        ms(r.extractMs),
                                        ms(r.ours.smoothMs),
                                        ms(r.ours.attributesMs),
                                        ms(r.ours.atlasMs),
                                        ms(total)};
        if (r.hasConstrained)
            row.push_back(ms(r.constrained.smoothMs));
        if (r.hasTaubin) {
            row.push_back(ms(r.taubin.smoothMs));
            row.push_back(ms(r.extractMs + r.taubin.smoothMs + r.taubin.attributesMs + r.taubin.atlasMs));
            row.push_back(ms(r.taubinToVcgMs));
        }
        times.rows.push_back(row);
    }
    out << times.markdown() << "\n";
}

void writeCounts(std::ostream &out, const std::vector<ModelRun> &runs) {
    // Table 2: counts per stage.
    out << "## Counts per stage (the paper's Table 2)\n\n"
        << "Voxels: the parts' bounding boxes; opaque: solid voxels. Fairing keeps the extracted mesh's counts. "
           "After the atlas a vertex is cloned once per chart it touches (section 4.5).\n\n";
    out << "The paper's Table 2 (after texture extraction):\n\n"
        << Table{{"model", "voxels", "opaque voxels", "vertices", "triangles"},
                 {{"Demo Truck", "21168", "7893", "8987", "13624"},
                  {"Kirov", "554880", "35841", "36005", "52620"},
                  {"Yuri Head", "391680", "42733", "98324", "121468"},
                  {"Warhammer", "429900", "63150", "89750", "185552"}}}
               .markdown()
        << "\nOurs:\n\n";
    Table counts{{"model", "kind", "parts", "voxels", "opaque voxels", "extracted vertices", "quads", "triangles (4.4)",
                  "atlas vertices", "atlas triangles", "charts", "texture"},
                 {},
                 2};
    for (const ModelRun &r : runs) {
        const Variant &o = r.ours;
        counts.rows.push_back(
            {r.name, r.kind, std::to_string(r.parts), std::to_string(r.boxVoxels), std::to_string(r.solidVoxels),
             std::to_string(r.raw.mesh.vertexCount()), std::to_string(r.raw.mesh.quadCount()),
             std::to_string(o.attributes.triangleCount()), o.hasAtlas ? std::to_string(o.atlasVertices) : "-",
             o.hasAtlas ? std::to_string(o.atlas.layout.wedgeUv.size() / 3) : "-",
             o.hasAtlas ? std::to_string(o.atlas.charts.chartCount()) : "-",
             o.hasAtlas ? format("%dx%d", o.atlas.texture.width, o.atlas.texture.height) : o.atlasError});
    }
    out << counts.markdown() << "\n";
}

void writeTaubinChain(std::ostream &out, const std::vector<ModelRun> &runs) {
    // The Taubin chain stage by stage, and the atlas on its surface.
    if (!runs.empty() && runs.front().hasTaubin) {
        out << "## Taubin chain, stage by stage\n\n"
            << "The same stages after Taubin Smooth instead of our fairing (extraction is shared), and how "
               "many charts the atlas makes of each smoothed surface.\n\n";
        Table taubin{
            {"model", "extraction", "Taubin 10", "attributes", "atlas", "total", "charts (Taubin)", "charts (ours)"},
            {}};
        for (const ModelRun &r : runs)
            taubin.rows.push_back({r.name, ms(r.extractMs), ms(r.taubin.smoothMs), ms(r.taubin.attributesMs),
                                   ms(r.taubin.atlasMs),
                                   ms(r.extractMs + r.taubin.smoothMs + r.taubin.attributesMs + r.taubin.atlasMs),
                                   r.taubin.hasAtlas ? std::to_string(r.taubin.atlas.charts.chartCount()) : "-",
                                   r.ours.hasAtlas ? std::to_string(r.ours.atlas.charts.chartCount()) : "-"});
        out << taubin.markdown() << "\n";
    }
}

void writeChange(std::ostream &out, const std::vector<ModelRun> &runs) {
    // Real models: no true surface, so how much each smoother changed the voxel surface.
    out << "## Change from the voxel surface (all inputs)\n\n"
        << "Enclosed volume against the raw voxel surface's, and vertex displacement from the lattice (voxels).\n\n";
    Table change{{"model", "method", "volume %", "mean move", "max move"}, {}, 2};
    for (const ModelRun &r : runs) {
        const double rawVolume = shapes::enclosedVolume(r.raw.mesh.positions, r.raw.attributes.triangles);
        for (const Variant *v : {&r.ours, &r.constrained, &r.taubin, &r.hc, &r.twoStep}) {
            if (v->mesh.positions.size() != r.raw.mesh.positions.size() || v->mesh.positions.empty())
                continue;
            double sum = 0, maxMove = 0;
            for (size_t i = 0; i < v->mesh.positions.size(); ++i) {
                const double d = glm::length(v->mesh.positions[i] - r.raw.mesh.positions[i]) / r.raw.mesh.voxelSize;
                sum += d;
                maxMove = std::max(maxMove, d);
            }
            const double volume = shapes::enclosedVolume(v->mesh.positions, r.raw.attributes.triangles);
            change.rows.push_back({r.name, v->name, format("%+.2f", (volume - rawVolume) / rawVolume * 100.0),
                                   format("%.3f", sum / double(v->mesh.positions.size())), format("%.3f", maxMove)});
        }
        if (r.hasVtk) {  // its own vertices: no displacement
            const double volume = shapes::enclosedVolume(r.vtk.positions, r.vtk.triangles);
            change.rows.push_back(
                {r.name, "VTK windowed sinc", format("%+.2f", (volume - rawVolume) / rawVolume * 100.0), "-", "-"});
        }
    }
    out << change.markdown() << "\n";
}

void writeFamilies(std::ostream &out, const std::filesystem::path &folder, int size) {
    // The shape families at random orientations and offsets.
    out << "## Shape families (random orientations and sub-voxel offsets)\n\n"
        << "Worst RMS distance to the true surface over 4 shapes of each family of testkit/shapes/shape_families.h "
           "(20k samples each), worst |volume change| in brackets; best smoothed value in bold.\n\n"
        << lineup::familyTable(4, 20000) << "\n"
        << lineup::familyPictures(folder, size / 2);
}

void writePictures(std::ostream &out, const std::vector<ModelRun> &runs, const std::vector<Pictures> &pictures) {
    // Pictures.
    out << "## Pictures\n\nSame camera for every panel of a model (3/4 view from above the front, z up). Geometry "
           "panels use the voxel colours and faceted shading, so only the shape differs; the last panel is the "
           "product: the faired mesh with its smoothed vertex normals and the baked atlas texture.\n\n";
    for (size_t i = 0; i < runs.size(); ++i) {
        const Pictures &p = pictures[i];
        out << "### " << runs[i].name << "\n\n";
        for (size_t k = 0; k < p.labels.size(); ++k)
            out << (k ? ", " : "Panels: ") << "[" << p.labels[k] << "](" << p.files[k] << ")";
        if (!p.wireframe.empty())
            out << ", [ours in wireframe](" << p.wireframe << ")";
        if (!p.texture.empty())
            out << "; [atlas texture](" << p.texture << ")";
        out << ".\n\n![" << runs[i].name << "](" << p.strip << ")\n\n";
    }
}

}  // namespace voxelfair::report
