// Prints how far each smoother leaves the voxel surface from the true surface of analytic
// shapes: the raw voxel quads, one pass of the paper's fairing (section 4.3) and, when built
// with vcglib, MeshLab's "Taubin Smooth" with its defaults on the same triangulation.
//
//   compare_smoothing [samples]       (default 200000 area-uniform samples per mesh)
//
// Distances are in voxels, measured from the samples to the exact SDF (see tests/shapes).
#include "fairing/smoothing_comparison.h"

#include <cstdio>
#include <cstdlib>

int main(int argc, char **argv) {
    voxelfair::comparison::Options options;
    if (argc > 1)
        options.samples = std::strtoul(argv[1], nullptr, 10);
#ifndef VOXELFAIR_HAVE_VCGLIB
    std::printf("(built without vcglib: no Taubin rows)\n");
#endif
    std::printf("%-16s %-16s %8s %8s %8s %10s\n", "shape", "method", "RMS", "max", "bias", "volume %");
    for (const voxelfair::shapes::Shape &shape : voxelfair::comparison::comparisonShapes()) {
        for (const voxelfair::comparison::Row &row : voxelfair::comparison::compare(shape, options))
            std::printf("%-16s %-16s %8.4f %8.4f %+8.4f %+10.2f\n", row.shape.c_str(), row.method.c_str(),
                        row.error.rms, row.error.max, row.error.bias, row.error.volumeChangePercent);
        std::printf("\n");
    }
    return 0;
}
