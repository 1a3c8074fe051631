// Prints how far each smoother leaves the voxel surface from the true surface of analytic
// shapes: the raw voxel quads, one pass of the paper's fairing (section 4.3), MeshLab's "Taubin
// Smooth" with its defaults on the same triangulation (when built with vcglib), and the second
// mode (fairing/constrained_fairing.h) with its defaults. Then, per shape family of the wider set
// the second mode is tested on (comparison::fidelityShapes), the worst and mean of each method.
//
//   compare_smoothing [samples]       (default 200000 area-uniform samples per mesh)
//
// Distances are in voxels, measured from the samples to the exact SDF (see tests/shapes).
#include "fairing/smoothing_comparison.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>

int main(int argc, char **argv) {
    using namespace voxelfair;
    comparison::Options options;
    if (argc > 1)
        options.samples = std::strtoul(argv[1], nullptr, 10);
#ifndef VOXELFAIR_HAVE_VCGLIB
    std::printf("(built without vcglib: no Taubin rows)\n");
#endif
    std::printf("%-16s %-16s %8s %8s %8s %10s\n", "shape", "method", "RMS", "max", "bias", "volume %");
    for (const shapes::Shape &shape : comparison::comparisonShapes()) {
        for (const comparison::Row &row : comparison::compare(shape, options))
            std::printf("%-16s %-16s %8.4f %8.4f %+8.4f %+10.2f\n", row.shape.c_str(), row.method.c_str(),
                        row.error.rms, row.error.max, row.error.bias, row.error.volumeChangePercent);
        std::printf("\n");
    }

    // Wider set: worst / mean RMS and worst |volume change| per (family, method).
    struct Summary {
        double worst = 0.0, sum = 0.0, worstVolume = 0.0;
        int count = 0;
    };
    std::map<std::pair<std::string, std::string>, Summary> summary;
    std::vector<std::string> methods;
    for (const comparison::FamilyShape &f : comparison::fidelityShapes())
        for (const comparison::Row &row : comparison::compare(f.shape, options)) {
            Summary &s = summary[{f.family, row.method}];
            s.worst = std::max(s.worst, row.error.rms);
            s.sum += row.error.rms;
            s.worstVolume = std::max(s.worstVolume, std::fabs(row.error.volumeChangePercent));
            ++s.count;
            if (std::find(methods.begin(), methods.end(), row.method) == methods.end())
                methods.push_back(row.method);
        }
    std::printf("%-10s %-16s %6s %10s %10s %12s\n", "family", "method", "shapes", "worst RMS", "mean RMS",
                "worst |vol|%");
    for (const char *family : {"sphere", "torus", "cylinder", "box"})
        for (const std::string &method : methods) {
            const Summary &s = summary[{family, method}];
            if (s.count)
                std::printf("%-10s %-16s %6d %10.4f %10.4f %12.2f\n", family, method.c_str(), s.count, s.worst,
                            s.sum / s.count, s.worstVolume);
        }
    return 0;
}
