#include "comparison_report/arguments.h"

#include "comparison_report/tables.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>

namespace fs = std::filesystem;

namespace voxelfair::report {

namespace {

// Two-colour 3D checker of 4-voxel blocks, so the pictures show whether the texture stays crisp.
Palette shapePalette() {
    Palette p;
    p.colours[1] = {214, 128, 64};
    p.colours[2] = {72, 132, 190};
    return p;
}

std::vector<std::string> sortedFiles(const fs::path &folder, const std::string &extension) {
    std::vector<std::string> files;
    if (fs::is_directory(folder))
        for (const auto &entry : fs::directory_iterator(folder))
            if (entry.path().extension() == extension)
                files.push_back(entry.path().string());
    std::sort(files.begin(), files.end());
    return files;
}

constexpr size_t kMinSolidVoxels = 500;  // smaller models (1x1x1, 3x3x3 test files) say nothing here

}  // namespace

bool parseArguments(int argc, char **argv, const fs::path &defaultFolder, Arguments &out) {
    out.folder = defaultFolder;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--size") == 0 && i + 1 < argc)
            out.size = std::max(64, std::atoi(argv[++i]));
        else if (std::strcmp(argv[i], "--only") == 0 && i + 1 < argc)
            out.only = argv[++i];
        else if (argv[i][0] == '-') {
            std::fprintf(stderr, "usage: %s [output folder] [--size pixels] [--only MODEL]\n", argv[0]);
            return false;
        } else
            out.folder = argv[i];
    }
    return true;
}

Inputs loadInputs(const fs::path &models, const std::vector<shapes::Shape> &shapeList, const std::string &only) {
    Inputs result;
    std::vector<Input> &inputs = result.inputs;
    std::vector<std::string> &skipped = result.skipped;
    for (const std::string &path : sortedFiles(models / "vxl", ".vxl")) {
        // A unit is shown whole under its body's name: its turret and barrel files not again.
        const std::string stem = fs::path(path).stem().string();
        bool companion = false;
        for (const char *suffix : {"tur", "barl"}) {
            const size_t n = std::strlen(suffix);
            companion =
                companion || (stem.size() > n && stem.compare(stem.size() - n, n, suffix) == 0 &&
                              fs::exists(fs::path(path).parent_path() / (stem.substr(0, stem.size() - n) + ".vxl")));
        }
        if (companion)
            continue;
        try {
            Input in{pipeline::loadVxl(path, (models / "pal").string(), true), "VXL"};
            if (in.model->solidVoxels() < kMinSolidVoxels)
                skipped.push_back(format("%s (%zu voxels)", in.model->name.c_str(), in.model->solidVoxels()));
            else
                inputs.push_back(std::move(in));
        } catch (const std::exception &e) {
            skipped.push_back(fs::path(path).filename().string() + " (" + e.what() + ")");
        }
    }
    for (const char *name : {"crabby", "robo", "8ontop"}) {
        try {
            inputs.push_back({pipeline::loadVox((models / "vox" / (std::string(name) + ".vox")).string()), "VOX"});
        } catch (const std::exception &e) {
            skipped.push_back(std::string(name) + ".vox (" + e.what() + ")");
        }
    }
    inputs.push_back({pipeline::syntheticTankModel(), "synthetic"});
    for (const shapes::Shape &shape : shapeList) {
        VoxelVolume volume = shapes::voxelize(shape, [](int x, int y, int z) {
            return Voxel{uint8_t(1 + (x / 4 + y / 4 + z / 4) % 2), 0};
        });
        inputs.push_back({pipeline::volumeModel(shape.name, std::move(volume), shapePalette()), "shape", &shape});
    }

    if (!only.empty())
        inputs.erase(
            std::remove_if(inputs.begin(), inputs.end(), [&](const Input &in) { return in.model->name != only; }),
            inputs.end());
    return result;
}

}  // namespace voxelfair::report
