// The report's command line and its inputs: the shared real models (VXL with the shared palettes,
// three VOX scenes), the synthetic tank and the voxelized analytic shapes.
#pragma once

#include "pipeline/pipeline_stages.h"
#include "shapes/analytic_shapes.h"
#include "shapes/synthetic_tank.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace voxelfair::report {

struct Arguments {
    std::filesystem::path folder;  // where report.md and the pictures go
    int size = 560;                // picture size in pixels
    std::string only;              // --only NAME: that model's pictures and rows alone (e.g. to refresh one strip)
};

// Parses `comparison_report [output folder] [--size N] [--only MODEL]`; false (after printing the usage) on a bad
// argument.
bool parseArguments(int argc, char **argv, const std::filesystem::path &defaultFolder, Arguments &out);

struct Input {
    std::unique_ptr<pipeline::Model> model;
    std::string kind;
    const shapes::Shape *shape = nullptr;
};

struct Inputs {
    std::vector<Input> inputs;
    std::vector<std::string> skipped;  // "name (why)": too small, or unreadable
};

// Loads every input; models that fail to load or are too small are listed in `skipped`.
// `shapes` must outlive the inputs (they point into it).
// With `only` non-empty, just the input of that name.
Inputs loadInputs(const std::filesystem::path &models, const std::vector<shapes::Shape> &shapes,
                  const std::string &only);

}  // namespace voxelfair::report
