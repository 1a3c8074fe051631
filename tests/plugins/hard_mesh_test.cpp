// The filters on hard meshes, through meshlabserver: several components, a non-manifold edge, a
// zero-area face, duplicated and isolated vertices, huge and tiny coordinates, a non-finite
// vertex, no colours. Every filter must finish (or fail with its own message), never crash, and
// never turn a finite coordinate or texture coordinate into NaN.
#include "meshlab_run.h"
#include "ply_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace fs = std::filesystem;

namespace {

// A unit cube (12 triangles), a fin of three triangles sharing one edge (non-manifold), a
// zero-area triangle, a duplicated vertex, an isolated vertex, a far-away huge triangle, a tiny
// one, and a triangle with a NaN corner. No colours.
std::string hardMeshPly(const std::string &dir) {
    std::vector<std::array<double, 3>> v = {
        {0, 0, 0},     {1, 0, 0},     {1, 1, 0},
        {0, 1, 0},     {0, 0, 1},     {1, 0, 1},
        {1, 1, 1},     {0, 1, 1},  // cube 0-7
        {3, 0, 0},     {3, 1, 0},     {4, 0, 0},
        {2, 0, 1},     {3, 0, 2},                              // fin 8-12
        {5, 0, 0},     {6, 0, 0},     {7, 0, 0},               // collinear 13-15
        {1, 1, 1},                                             // duplicate of 6: 16
        {9, 9, 9},                                             // isolated 17
        {1e25, 0, 0},  {0, 1e25, 0},  {0, 0, 1e25},            // huge 18-20
        {1e-25, 0, 0}, {0, 1e-25, 0}, {0, 0, 1e-25},           // tiny 21-23
        {10, 10, 10},  {11, 10, 10},  {std::nan(""), 11, 10},  // NaN 24-26
    };
    std::vector<std::array<int, 3>> f = {
        {0, 2, 1},    {0, 3, 2},    {4, 5, 6},    {4, 6, 7},  {0, 1, 5}, {0, 5, 4},
        {1, 2, 6},    {1, 6, 5},    {2, 3, 7},    {2, 7, 16}, {3, 0, 4}, {3, 4, 7},  // cube, one corner duplicated
        {8, 9, 10},   {8, 9, 11},   {8, 9, 12},                                      // three faces on edge 8-9
        {13, 14, 15},                                                                // zero area
        {18, 19, 20}, {21, 22, 23}, {24, 25, 26},
    };
    const std::string path = dir + "/hard.ply";
    std::ofstream out(path);
    out << "ply\nformat ascii 1.0\nelement vertex " << v.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << f.size()
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto &p : v)
        out << p[0] << " " << p[1] << " " << p[2] << "\n";
    for (const auto &t : f)
        out << "3 " << t[0] << " " << t[1] << " " << t[2] << "\n";
    return path;
}

std::string script(const std::string &dir, int mode) {
    std::ostringstream s;
    s << "<!DOCTYPE FilterScript>\n<FilterScript>\n"
      << " <filter name=\"Voxel Fairing: Modified Lanczos\">\n"
      << "  <Param type=\"RichEnum\" name=\"mode\" value=\"" << mode
      << "\" enum_cardinality=\"2\" enum_val0=\"Paper\" enum_val1=\"Constrained\"/>\n"
      << "  <Param type=\"RichFloat\" name=\"lambda\" value=\"1.3333334\"/>\n"
      << "  <Param type=\"RichInt\" name=\"passes\" value=\"1\"/>\n"
      << "  <Param type=\"RichFloat\" name=\"voxelSize\" value=\"0\"/>\n"
      << "  <Param type=\"RichBool\" name=\"Selected\" value=\"false\"/>\n </filter>\n"
      << " <filter name=\"Voxel Fairing: Attribute Smoothing\">\n"
      << "  <Param type=\"RichBool\" name=\"distinctNormals\" value=\"true\"/>\n"
      << "  <Param type=\"RichBool\" name=\"triangulate\" value=\"true\"/>\n </filter>\n"
      << " <filter name=\"Voxel Texture Atlas: Greedy Charts\">\n"
      << "  <Param type=\"RichFloat\" name=\"chartAngle\" value=\"45.573\"/>\n"
      << "  <Param type=\"RichEnum\" name=\"packing\" value=\"0\" enum_cardinality=\"2\" enum_val0=\"Tight\" "
         "enum_val1=\"Paper\"/>\n"
      << "  <Param type=\"RichFloat\" name=\"texelsPerVoxel\" value=\"8\"/>\n"
      << "  <Param type=\"RichInt\" name=\"textureSize\" value=\"0\"/>\n"
      << "  <Param type=\"RichBool\" name=\"fillTexture\" value=\"true\"/>\n"
      << "  <Param type=\"RichBool\" name=\"wideTextures\" value=\"true\"/>\n"
      << "  <Param type=\"RichInt\" name=\"maxTextureSize\" value=\"4096\"/>\n"
      << "  <Param type=\"RichFloat\" name=\"voxelSize\" value=\"0\"/>\n"
      << "  <Param type=\"RichInt\" name=\"gutter\" value=\"4\"/>\n"
      << "  <Param type=\"RichEnum\" name=\"colours\" value=\"0\" enum_cardinality=\"2\" enum_val0=\"Crisp voxel "
         "colours\" enum_val1=\"Smoothed vertex colours\"/>\n"
      << "  <Param type=\"RichString\" name=\"textureFile\" value=\"" << dir << "/hard_texture.png\"/>\n </filter>\n"
      << "</FilterScript>\n";
    const std::string path = dir + "/hard.mlx";
    std::ofstream(path) << s.str();
    return path;
}

}  // namespace

TEST(HardMeshes, FiltersFinishWithoutCrashOrNewNaN) {
    for (int mode : {0, 1}) {
        SCOPED_TRACE(mode == 0 ? "paper mode" : "constrained mode");
        const std::string dir = makeTempDir();
        const std::string input = hardMeshPly(dir);
        const PlyMesh before = readAsciiPly(input);
        const MeshlabRun run =
            runMeshlabServer({"-i", input, "-o", dir + "/out.ply", "-m", "wt", "sa", "-s", script(dir, mode)});
        // meshlabserver exits 134 on an assert or uncaught exception, 255 when a filter fails.
        ASSERT_NE(run.exitCode, 134) << run.output;
        ASSERT_EQ(run.exitCode, 0) << run.output;
        EXPECT_NE(run.output.find("Voxel Fairing: "), std::string::npos) << run.output;
        EXPECT_NE(run.output.find("Texture Atlas: "), std::string::npos) << run.output;
        EXPECT_NE(run.output.find("no face colours"), std::string::npos) << "the missing colours are not reported\n"
                                                                         << run.output;
        const PlyMesh after = readAsciiPly(dir + "/out.ply");
        ASSERT_EQ(after.positions.size(), before.positions.size());
        for (size_t v = 0; v < after.positions.size(); ++v)
            for (int k = 0; k < 3; ++k) {
                if (std::isfinite(before.positions[v][size_t(k)])) {
                    EXPECT_TRUE(std::isfinite(after.positions[v][size_t(k)])) << "vertex " << v << "\n" << run.output;
                }
            }
        ASSERT_EQ(after.wedgeUv.size(), after.triangles.size());
        for (const auto &uv : after.wedgeUv)
            for (float x : uv)
                EXPECT_TRUE(std::isfinite(x) && x >= 0.0f && x <= 1.0f);
        EXPECT_TRUE(fs::exists(dir + "/hard_texture.png"));
        fs::remove_all(dir);
    }
}

// An unwritable texture path fails the filter with the path it tried, and nothing is saved.
TEST(HardMeshes, UnwritableTexturePathIsNamed) {
    const std::string dir = makeTempDir();
    const std::string input = hardMeshPly(dir);
    std::string text;
    {
        std::ifstream in(script(dir, 0));
        text.assign(std::istreambuf_iterator<char>(in), {});
    }
    const std::string bad = "/proc/voxelfair/cannot/hard_texture.png";
    const std::string good = dir + "/hard_texture.png";
    text.replace(text.find(good), good.size(), bad);
    std::ofstream(dir + "/bad.mlx") << text;
    const MeshlabRun run = runMeshlabServer({"-i", input, "-o", dir + "/out.ply", "-s", dir + "/bad.mlx"});
    EXPECT_NE(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("could not write the texture to " + bad), std::string::npos) << run.output;
    fs::remove_all(dir);
}
