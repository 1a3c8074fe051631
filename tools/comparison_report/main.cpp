// The comparison report: how our chain (paper §4.2-4.5) compares with MeshLab's smoothers (vcglib's
// Taubin, HC Laplacian, TwoStep) and VTK's windowed sinc on the shared real models and on voxelized
// analytic shapes, in numbers and pictures.
//
//   comparison_report [output folder] [--size N] [--only MODEL]   (default folder: <build>/report, N = 560)
//
// Writes <folder>/report.md (also printed) and, per model, PNG pictures seen from the same
// camera: raw voxels, Taubin (10 steps), ours (one pass of the paper's fairing), the constrained
// mode, and ours textured with the baked atlas; plus the atlas texture and all panels side by side
// (<model>_strip.png). Times are the best of a few runs in this process, single-threaded;
// benchmarks/pipeline_benchmark measures the same stages with Google Benchmark.
//
// The parts: arguments.h (command line, inputs), runs.h (the chain per input, timed), pictures.h,
// sections.h (the Markdown sections), tables.h (formatting).
#include "comparison_report/arguments.h"
#include "comparison_report/pictures.h"
#include "comparison_report/runs.h"
#include "comparison_report/sections.h"
#include "smoothers/smoothing_comparison.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace fs = std::filesystem;
using namespace voxelfair;
using namespace voxelfair::report;

int main(int argc, char **argv) {
    Arguments args;
    if (!parseArguments(argc, argv, VOXELFAIR_DEFAULT_REPORT_DIR, args))
        return 2;
    std::error_code ec;
    fs::create_directories(args.folder, ec);
    if (ec) {
        std::fprintf(stderr, "%s: %s\n", args.folder.string().c_str(), ec.message().c_str());
        return 1;
    }

    const std::vector<shapes::Shape> shapeList = comparison::comparisonShapes();
    const Inputs inputs = loadInputs(VOXELFAIR_MODELS_DIR, shapeList, args.only);
    std::vector<ModelRun> runs;
    std::vector<Pictures> pictures;
    for (const Input &in : inputs.inputs) {
        std::fprintf(stderr, "%s...\n", in.model->name.c_str());
        runs.push_back(runChain(*in.model, in.kind));
        runs.back().shape = in.shape;
        pictures.push_back(renderPictures(runs.back(), args.folder, args.size));
    }

    std::ostringstream md;
    writeIntroduction(md, inputs.skipped);
    writeFidelity(md, runs);
    writeTimes(md, runs);
    writeCounts(md, runs);
    writeTaubinChain(md, runs);
    writeChange(md, runs);
    writeFamilies(md, args.folder, args.size);
    writePictures(md, runs, pictures);

    const std::string text = md.str();
    std::ofstream((args.folder / "report.md").string()) << text;
    std::fputs(text.c_str(), stdout);
    std::fprintf(stderr, "wrote %s\n", (args.folder / "report.md").string().c_str());
    return 0;
}
