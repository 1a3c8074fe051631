// VTK's answer for one voxel model, for the wrapper's --mode compare
// (meshlab_scripts/voxelfair_convert.py): every part through discrete marching cubes and the
// windowed sinc filter with its defaults (tools/smoother_lineup.h, testkit/smoothers/vtk_windowed_sinc.h),
// placed in model space, written as an ASCII PLY of triangles.
//
//   voxelfair_vtk_smooth INPUT.vxl|INPUT.vox OUTPUT.ply [--palettes FOLDER]
//
// Bad input: a message naming the file and the problem, exit 1; nothing is written.
#include "pipeline/pipeline_stages.h"
#include "smoother_lineup.h"

#include <cstdio>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <string>

int main(int argc, char **argv) {
    using namespace voxelfair;
    std::string input, output, palettes;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--palettes") == 0 && i + 1 < argc)
            palettes = argv[++i];
        else if (input.empty())
            input = argv[i];
        else if (output.empty())
            output = argv[i];
        else
            input.clear();
    }
    if (input.empty() || output.empty()) {
        std::fprintf(stderr, "usage: %s INPUT.vxl|INPUT.vox OUTPUT.ply [--palettes FOLDER]\n", argv[0]);
        return 2;
    }
    try {
        const std::string extension = std::filesystem::path(input).extension().string();
        std::unique_ptr<pipeline::Model> model =
            extension == ".vox" || extension == ".VOX" ? pipeline::loadVox(input) : pipeline::loadVxl(input, palettes);
        const lineup::TriangleSurface surface = lineup::vtkSurface(*model);
        const std::string partial = output + ".part";
        {
            std::ofstream out(partial);
            out << "ply\nformat ascii 1.0\ncomment VTK discrete marching cubes + windowed sinc (20 iterations)\n"
                << "element vertex " << surface.displayPositions.size() << "\nproperty float x\nproperty float y\n"
                << "property float z\nelement face " << surface.triangles.size() / 3
                << "\nproperty list uchar int vertex_indices\nend_header\n";
            for (const glm::vec3 &p : surface.displayPositions)
                out << p.x << ' ' << p.y << ' ' << p.z << '\n';
            for (size_t t = 0; t + 2 < surface.triangles.size(); t += 3)
                out << "3 " << surface.triangles[t] << ' ' << surface.triangles[t + 1] << ' '
                    << surface.triangles[t + 2] << '\n';
            if (!out) {
                std::fprintf(stderr, "voxelfair_vtk_smooth: %s: could not write\n", output.c_str());
                return 1;
            }
        }
        std::filesystem::rename(partial, output);
    } catch (const std::exception &e) {
        std::fprintf(stderr, "voxelfair_vtk_smooth: %s: %s\n", input.c_str(), e.what());
        return 1;
    }
    return 0;
}
