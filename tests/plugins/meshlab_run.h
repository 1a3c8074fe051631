// Runs the staged meshlabserver headless (under xvfb-run) for end-to-end tests.
#pragma once

#include <map>
#include <string>
#include <vector>

struct MeshlabRun {
    int exitCode = -1;
    std::string output;  // stdout and stderr together
};

// Runs `meshlabserver args...` with the given extra environment (e.g. VOXELFAIR_PALETTE), in
// private XDG folders so nothing is written to the user's home.
MeshlabRun runMeshlabServer(const std::vector<std::string> &args, const std::map<std::string, std::string> &env = {});

// A fresh temporary folder for a test's outputs.
std::string makeTempDir();
