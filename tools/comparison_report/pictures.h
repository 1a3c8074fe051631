// The report's pictures of one input: every variant from the same camera, the textured product,
// a wireframe, the atlas texture and the strip of all panels side by side.
#pragma once

#include "comparison_report/runs.h"

#include <filesystem>
#include <string>
#include <vector>

namespace voxelfair::report {

struct Pictures {
    std::vector<std::string> files;  // panel files, in panel order
    std::vector<std::string> labels;
    std::string strip, texture, wireframe;
};

// Renders the panels of `run` into `folder` at `size` pixels; returns their file names.
Pictures renderPictures(const ModelRun &run, const std::filesystem::path &folder, int size);

}  // namespace voxelfair::report
