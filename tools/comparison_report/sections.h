// The report's sections, each appended to `out` as Markdown: the introduction, fidelity on the
// analytic shapes, the paper's Tables 1 and 2 beside ours, the Taubin chain, the change from the
// voxel surface, the shape families, the pictures.
#pragma once

#include "comparison_report/pictures.h"
#include "comparison_report/runs.h"

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace voxelfair::report {

void writeIntroduction(std::ostream &out, const std::vector<std::string> &skipped);
void writeFidelity(std::ostream &out, const std::vector<ModelRun> &runs);
void writeTimes(std::ostream &out, const std::vector<ModelRun> &runs);
void writeCounts(std::ostream &out, const std::vector<ModelRun> &runs);
void writeTaubinChain(std::ostream &out, const std::vector<ModelRun> &runs);
void writeChange(std::ostream &out, const std::vector<ModelRun> &runs);
void writeFamilies(std::ostream &out, const std::filesystem::path &folder, int size);
void writePictures(std::ostream &out, const std::vector<ModelRun> &runs, const std::vector<Pictures> &pictures);

}  // namespace voxelfair::report
