// Prints how far each smoother leaves the voxel surface from the true surface of analytic shapes:
// the raw voxel quads, one pass of the paper's fairing (section 4.3), MeshLab's Taubin Smooth, HC
// Laplacian Smooth and TwoStep Smooth with their defaults on the same triangulation (when built
// with vcglib), VTK's discrete marching cubes + windowed sinc (when built with VTK), and the
// constrained mode (fairing/constrained_fairing.h) with its defaults.
//
//   compare_smoothing [samples] [instances]   (defaults: 200000 area-uniform samples per mesh,
//                                              4 instances per shape family)
//
// First the fixed shapes one by one; then one table over every family: the fixed families the
// constrained mode was first tested on (comparison::fidelityShapes) and the families at random
// orientations and sub-voxel offsets of testkit/shapes/shape_families.h. Each cell: worst RMS
// distance in voxels over the family's shapes, and the worst |volume change|.
#include "smoothers/smoothing_comparison.h"
#include "shapes/shape_families.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

int main(int argc, char **argv) {
    using namespace voxelfair;
    comparison::Options options;
    if (argc > 1)
        options.samples = std::strtoul(argv[1], nullptr, 10);
    const int instances = argc > 2 ? std::atoi(argv[2]) : 4;
#ifndef VOXELFAIR_HAVE_VCGLIB
    std::printf("(built without vcglib: no MeshLab rows)\n");
#endif
#ifndef VOXELFAIR_HAVE_VTK
    std::printf("(built without VTK: no VTK rows)\n");
#endif
    std::printf("%-16s %-18s %8s %8s %8s %10s\n", "shape", "method", "RMS", "max", "bias", "volume %");
    for (const shapes::Shape &shape : comparison::comparisonShapes()) {
        for (const comparison::Row &row : comparison::compare(shape, options))
            std::printf("%-16s %-18s %8.4f %8.4f %+8.4f %+10.2f\n", row.shape.c_str(), row.method.c_str(),
                        row.error.rms, row.error.max, row.error.bias, row.error.volumeChangePercent);
        std::printf("\n");
    }

    // One table: worst RMS and worst |volume change| per (family, method).
    struct Summary {
        double worst = 0.0, worstVolume = 0.0;
        int count = 0;
    };
    std::map<std::pair<std::string, std::string>, Summary> summary;
    std::vector<std::string> methods, families;
    auto add = [&](const std::string &family, const shapes::Shape &shape) {
        if (std::find(families.begin(), families.end(), family) == families.end())
            families.push_back(family);
        for (const comparison::Row &row : comparison::compare(shape, options)) {
            Summary &s = summary[{family, row.method}];
            s.worst = std::max(s.worst, row.error.rms);
            s.worstVolume = std::max(s.worstVolume, std::fabs(row.error.volumeChangePercent));
            ++s.count;
            if (std::find(methods.begin(), methods.end(), row.method) == methods.end())
                methods.push_back(row.method);
        }
    };
    for (const comparison::FamilyShape &f : comparison::fidelityShapes())
        add(f.family + " (fixed)", f.shape);
    for (const shapes::FamilyShape &f : shapes::familyShapes(instances))
        add(f.family, f.shape);

    std::printf("Worst RMS distance to the true surface (voxels) and worst |volume change| per family\n\n");
    std::printf("| family | shapes |");
    for (const std::string &method : methods)
        std::printf(" %s |", method.c_str());
    std::printf("\n|---|---|");
    for (size_t i = 0; i < methods.size(); ++i)
        std::printf("---|");
    std::printf("\n");
    for (const std::string &family : families) {
        std::printf("| %s | %d |", family.c_str(), summary[{family, methods.front()}].count);
        // The best smoothed method (not the raw voxels) in bold.
        double best = 1e30;
        for (const std::string &method : methods)
            if (method != comparison::kRawMethod)
                best = std::min(best, summary[{family, method}].worst);
        for (const std::string &method : methods) {
            const Summary &s = summary[{family, method}];
            const bool bold = method != comparison::kRawMethod && s.worst == best;
            std::printf(" %s%.3f%s (%.1f%%) |", bold ? "**" : "", s.worst, bold ? "**" : "", s.worstVolume);
        }
        std::printf("\n");
    }
    return 0;
}
