// End-to-end tests through the real meshlabserver: our importer is loaded from the staged
// runtime, imports .vxl files and MeshLab saves them; the saved PLY must equal what the
// host-free units compute in this process.
#include "fixtures/tdcz_writer.h"
#include "meshlab_run.h"
#include "ply_reader.h"

#include "attributes/vertex_colours.h"
#include "fairing/lanczos_fairing.h"
#include "formats/file_bytes.h"
#include "formats/vox.h"
#include "formats/hva.h"
#include "formats/vxl.h"
#include "scene/vox_scene.h"
#include "scene/vxl_scene.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>

using namespace voxelfair;
namespace fs = std::filesystem;

namespace {

const std::string kModels = std::string(VOXELFAIR_MODELS_DIR) + "/vxl";
const std::string kPalettes = std::string(VOXELFAIR_MODELS_DIR) + "/pal";

// What io_vxl should produce for `vxlPath` with default settings (and an optional .pal).
SceneSurface expectedSurface(const std::string &vxlPath, const std::string &palPath = "") {
    const std::vector<uint8_t> bytes = readFileBytes(vxlPath);
    const VxlModel model = readVxl(bytes.data(), bytes.size());
    std::unique_ptr<HvaAnimation> hva;
    const fs::path hvaPath = fs::path(vxlPath).replace_extension(".hva");
    if (fs::exists(hvaPath)) {
        const std::vector<uint8_t> h = readFileBytes(hvaPath.string());
        hva = std::make_unique<HvaAnimation>(readHva(h.data(), h.size()));
    }
    Palette external;
    VxlSceneOptions options;
    if (!palPath.empty()) {
        const std::vector<uint8_t> p = readFileBytes(palPath);
        external = readPal(p.data(), p.size());
        options.externalPalette = &external;
    }
    return extractSceneSurface(vxlScene(model, hva.get(), options));
}

// Imports `vxlPath` with meshlabserver and saves an ASCII PLY with face colour and quality.
// `log` receives what meshlabserver printed, our importer's report included.
PlyMesh importWithMeshLab(const std::string &vxlPath, const std::map<std::string, std::string> &env = {},
                          std::string *log = nullptr) {
    const std::string dir = makeTempDir();
    const std::string ply = dir + "/out.ply";
    const MeshlabRun run = runMeshlabServer({"-i", vxlPath, "-o", ply, "-m", "fc", "fq", "sa"}, env);
    EXPECT_EQ(run.exitCode, 0) << run.output;
    EXPECT_TRUE(fs::exists(ply)) << "meshlabserver did not save " << ply << "\n" << run.output;
    if (log)
        *log = run.output;
    PlyMesh mesh = fs::exists(ply) ? readAsciiPly(ply) : PlyMesh{};
    fs::remove_all(dir);
    return mesh;
}

// The saved mesh is the expected quad surface: same vertices in order, each quad as two
// triangles over its four corners, with the quad's colour and section.
void expectSameSurface(const PlyMesh &ply, const SceneSurface &expected) {
    ASSERT_EQ(ply.positions.size(), expected.positions.size());
    ASSERT_EQ(ply.triangles.size(), 2 * expected.quadCount());
    ASSERT_EQ(ply.faceColours.size(), ply.triangles.size());
    ASSERT_EQ(ply.faceQuality.size(), ply.triangles.size());
    for (size_t v = 0; v < ply.positions.size(); ++v)
        for (int k = 0; k < 3; ++k)
            ASSERT_NEAR(ply.positions[v][k], expected.positions[v][size_t(k)], 1e-3) << "vertex " << v;
    for (size_t q = 0; q < expected.quadCount(); ++q) {
        const uint32_t *c = &expected.quads[4 * q];
        const auto &t0 = ply.triangles[2 * q], &t1 = ply.triangles[2 * q + 1];
        EXPECT_EQ(t0, (std::array<uint32_t, 3>{c[0], c[1], c[2]})) << "quad " << q;
        EXPECT_EQ(t1, (std::array<uint32_t, 3>{c[0], c[2], c[3]})) << "quad " << q;
        const Rgb rgb = expected.quadColours[q];
        for (size_t t = 2 * q; t < 2 * q + 2; ++t) {
            EXPECT_EQ(ply.faceColours[t], (std::array<uint8_t, 4>{rgb.r, rgb.g, rgb.b, 255})) << "face " << t;
            EXPECT_EQ(ply.faceQuality[t], float(expected.quadParts[q])) << "face " << t;
        }
    }
}

bool haveModels() { return fs::is_directory(kModels); }

const std::string kVoxModels = std::string(VOXELFAIR_MODELS_DIR) + "/vox";

SceneSurface expectedVoxSurface(const std::string &voxPath, int frame = 0) {
    const std::vector<uint8_t> bytes = readFileBytes(voxPath);
    const VoxFile file = readVox(bytes.data(), bytes.size());
    return extractSceneSurface(voxScene(file, VoxSceneOptions{frame}));
}

std::string writeTempFile(const std::string &name, const std::vector<uint8_t> &bytes) {
    const std::string path = makeTempDir() + "/" + name;
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char *>(bytes.data()), std::streamsize(bytes.size()));
    return path;
}

}  // namespace

TEST(MeshlabServer, ImportsTheExampleTankWithColoursAndSections) {
    const std::string tank = std::string(VOXELFAIR_EXAMPLE_DIR) + "/tank.vxl";
    std::string log;
    const PlyMesh ply = importWithMeshLab(tank, {}, &log);
    const SceneSurface expected = expectedSurface(tank);
    ASSERT_GT(expected.quadCount(), 1000u);
    expectSameSurface(ply, expected);
    // Three sections, each face tagged with its own.
    EXPECT_EQ(expected.partQuadCounts.size(), 3u);
    EXPECT_NE(log.find("3 of 3 sections imported"), std::string::npos) << log;
    EXPECT_NE(log.find("non-manifold edges"), std::string::npos) << log;
}

TEST(MeshlabServer, ImportsSharedModelsWithAndWithoutAPalette) {
    if (!haveModels())
        GTEST_SKIP() << "the shared models are absent: " << kModels;
    for (const char *name : {"3tnk", "hmec", "subapc", "legs", "ttnkbarl"}) {
        SCOPED_TRACE(name);
        const std::string vxl = kModels + "/" + name + ".vxl";
        // The body alone: with the unit on, 3tnk brings its turret and barrel (unit_export_test.cpp).
        expectSameSurface(importWithMeshLab(vxl, {{"VOXELFAIR_UNIT", "0"}}), expectedSurface(vxl));
    }
    const std::string cc = kModels + "/cc.vxl", pal = kPalettes + "/ra2_unittem.pal";
    expectSameSurface(importWithMeshLab(cc, {{"VOXELFAIR_PALETTE", pal}}), expectedSurface(cc, pal));
}

TEST(MeshlabServer, ReportsManifoldSplitsInTheLog) {
    if (!haveModels())
        GTEST_SKIP() << "the shared models are absent: " << kModels;
    const std::string vxl = kModels + "/subapc.vxl";
    const SceneSurface expected = expectedSurface(vxl);
    std::string log;
    importWithMeshLab(vxl, {}, &log);
    const std::string line = std::to_string(expected.stats.nonManifoldEdgesSplit) + " non-manifold edges and " +
                             std::to_string(expected.stats.nonManifoldVerticesSplit) + " non-manifold vertices split";
    EXPECT_NE(log.find(line), std::string::npos) << "expected \"" << line << "\" in\n" << log;
}

// Bad input: meshlabserver fails and our message, naming the file and the problem, is on stderr.
TEST(MeshlabServer, BadInputGivesAClearErrorNamingTheFile) {
    const std::vector<uint8_t> tank = readFileBytes(std::string(VOXELFAIR_EXAMPLE_DIR) + "/tank.vxl");
    struct Case {
        std::string name;
        std::vector<uint8_t> bytes;
        std::string expected;  // part of the message
    };
    const std::vector<Case> cases = {
        {"truncated.vxl", std::vector<uint8_t>(tank.begin(), tank.begin() + long(tank.size() / 2)), "truncated.vxl"},
        {"aceofspades.vxl", std::vector<uint8_t>(4096, 0x01), "Ace of Spades"},
        {"empty.vxl", {}, "empty.vxl"},
    };
    for (const Case &c : cases) {
        SCOPED_TRACE(c.name);
        const std::string path = writeTempFile(c.name, c.bytes);
        const std::string dir = fs::path(path).parent_path().string();
        const MeshlabRun run = runMeshlabServer({"-i", path, "-o", dir + "/out.ply"});
        EXPECT_NE(run.exitCode, 0) << run.output;
        EXPECT_FALSE(fs::exists(dir + "/out.ply"));
        EXPECT_NE(run.output.find("io_vxl: "), std::string::npos) << run.output;
        EXPECT_NE(run.output.find(c.expected), std::string::npos) << run.output;
        fs::remove_all(dir);
    }
}

TEST(MeshlabServer, MissingOrBrokenCompanionFilesAreNamed) {
    const std::string dir = makeTempDir();
    fs::copy_file(std::string(VOXELFAIR_EXAMPLE_DIR) + "/tank.vxl", dir + "/tank.vxl");
    std::ofstream(dir + "/tank.hva", std::ios::binary) << "not an hva";
    MeshlabRun run = runMeshlabServer({"-i", dir + "/tank.vxl", "-o", dir + "/out.ply"});
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.output.find(dir + "/tank.hva"), std::string::npos) << run.output;

    fs::remove(dir + "/tank.hva");
    run =
        runMeshlabServer({"-i", dir + "/tank.vxl", "-o", dir + "/out.ply"}, {{"VOXELFAIR_PALETTE", dir + "/none.pal"}});
    EXPECT_NE(run.exitCode, 0);
    EXPECT_NE(run.output.find(dir + "/none.pal"), std::string::npos) << run.output;
    fs::remove_all(dir);
}

TEST(MeshlabServer, ListsOurFilters) {
    const std::string dir = makeTempDir();
    const MeshlabRun run = runMeshlabServer({"-d", dir + "/filters.html"});
    std::ifstream in(dir + "/filters.html");
    const std::string html(std::istreambuf_iterator<char>(in), {});
    EXPECT_NE(html.find("Voxel"), std::string::npos) << run.output;
    for (const char *name : {"Voxel Texture: Bake House Colour Mask", "Voxel Texture: Bake Material Maps"})
        EXPECT_NE(html.find(name), std::string::npos) << name;
    fs::remove_all(dir);
}

TEST(MeshlabServer, ImportsSharedVoxFilesLikeTheHostFreeReader) {
    if (!fs::is_directory(kVoxModels))
        GTEST_SKIP() << "the shared models are absent: " << kVoxModels;
    for (const char *name : {"robo", "crabby", "8ontop", "test-transform", "teardown"}) {
        SCOPED_TRACE(name);
        const std::string vox = kVoxModels + "/" + name + ".vox";
        std::string log;
        const PlyMesh ply = importWithMeshLab(vox, {}, &log);
        const SceneSurface expected = expectedVoxSurface(vox);
        ASSERT_GT(expected.quadCount(), 0u);
        expectSameSurface(ply, expected);
        EXPECT_NE(log.find("instances shown at frame 0"), std::string::npos) << log;
    }
}

TEST(MeshlabServer, CorruptCompressedVoxelsAreNamed) {
    // A Teardown TDCZ model whose zlib stream is broken: the error names the file and the problem.
    const std::string dir = makeTempDir();
    const std::string vox = dir + "/corrupt.vox";
    fixtures::Bytes content = fixtures::tdczContent(2, 2, 2, fixtures::Bytes(8, 3));
    content[14] = 0xff;  // the first deflate block: type 3 is reserved
    const fixtures::Bytes bytes = fixtures::VoxWriter().size(2, 2, 2).chunk("TDCZ", content).bytes();
    std::ofstream(vox, std::ios::binary).write(reinterpret_cast<const char *>(bytes.data()), bytes.size());
    const MeshlabRun run = runMeshlabServer({"-i", vox, "-o", dir + "/out.ply"});
    EXPECT_NE(run.exitCode, 0);
    EXPECT_FALSE(fs::exists(dir + "/out.ply"));
    EXPECT_NE(run.output.find("io_vxl: " + fs::canonical(vox).string() + ": "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("corrupt zlib data"), std::string::npos) << run.output;
    fs::remove_all(dir);
}

namespace {

std::string writeScript(const std::string &dir, const std::string &filters) {
    const std::string path = dir + "/script.mlx";
    std::ofstream(path) << "<!DOCTYPE FilterScript>\n<FilterScript>\n" << filters << "</FilterScript>\n";
    return path;
}

const char *kFairingFilter = R"(<filter name="Voxel Fairing: Modified Lanczos">
 <Param type="RichEnum" name="mode" value="0" enum_cardinality="2" enum_val0="Paper" enum_val1="Constrained"/>
 <Param type="RichFloat" name="lambda" value="1.33333337"/>
 <Param type="RichInt" name="passes" value="1"/>
 <Param type="RichFloat" name="voxelSize" value="0"/>
 <Param type="RichBool" name="Selected" value="false"/>
</filter>
)";

const char *kAttributeFilter = R"(<filter name="Voxel Fairing: Attribute Smoothing">
 <Param type="RichBool" name="distinctNormals" value="true"/>
 <Param type="RichBool" name="triangulate" value="true"/>
</filter>
)";

}  // namespace

// The MeshLab filter gives the host-free unit's result, vertex for vertex.
TEST(MeshlabServer, FairingFilterMatchesTheHostFreeUnit) {
    const std::string tank = std::string(VOXELFAIR_EXAMPLE_DIR) + "/tank.vxl";
    SceneSurface expected = expectedSurface(tank);
    std::vector<uint32_t> offsets(expected.quadCount() + 1);
    for (size_t q = 0; q < offsets.size(); ++q)
        offsets[q] = uint32_t(4 * q);
    const FairingReport report = fairModifiedLanczos({expected.positions.data(), expected.positions.size(),
                                                      offsets.data(), expected.quads.data(), expected.quadCount()},
                                                     nullptr);
    ASSERT_EQ(report.status, FairingStatus::Ok);
    ASSERT_GT(report.movedVertices, expected.positions.size() / 4);

    const std::string dir = makeTempDir();
    const MeshlabRun run = runMeshlabServer(
        {"-i", tank, "-o", dir + "/out.ply", "-m", "fc", "fq", "sa", "-s", writeScript(dir, kFairingFilter)});
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("Voxel Fairing: 1 pass(es)"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(std::to_string(report.movedVertices) + " vertices moved"), std::string::npos)
        << run.output;
    expectSameSurface(readAsciiPly(dir + "/out.ply"), expected);
    fs::remove_all(dir);
}

// Attribute smoothing after fairing: triangles only, unit vertex normals, vertex colours equal to
// the mean of the adjacent quads' colours.
TEST(MeshlabServer, AttributeSmoothingGivesVertexColoursAndNormals) {
    const std::string tank = std::string(VOXELFAIR_EXAMPLE_DIR) + "/tank.vxl";
    const SceneSurface expected = expectedSurface(tank);
    std::vector<uint32_t> offsets(expected.quadCount() + 1);
    for (size_t q = 0; q < offsets.size(); ++q)
        offsets[q] = uint32_t(4 * q);
    std::vector<glm::vec4> quadColours(expected.quadCount()), vertexColours(expected.positions.size());
    for (size_t q = 0; q < quadColours.size(); ++q)
        quadColours[q] =
            glm::vec4(expected.quadColours[q].r, expected.quadColours[q].g, expected.quadColours[q].b, 255);
    computeVertexColours({nullptr, expected.positions.size(), offsets.data(), expected.quads.data(),
                          expected.quadCount(), quadColours.data()},
                         vertexColours.data());

    const std::string dir = makeTempDir();
    const MeshlabRun run = runMeshlabServer({"-i", tank, "-o", dir + "/out.ply", "-m", "vc", "vn", "sa", "-s",
                                             writeScript(dir, std::string(kFairingFilter) + kAttributeFilter)});
    ASSERT_EQ(run.exitCode, 0) << run.output;
    std::ifstream in(dir + "/out.ply");
    std::string line;
    size_t vertices = 0;
    bool hasNormals = false, hasColours = false;
    while (std::getline(in, line) && line != "end_header") {
        if (line.rfind("element vertex", 0) == 0)
            vertices = std::stoul(line.substr(15));
        hasNormals |= line == "property float nx";
        hasColours |= line == "property uchar red";
    }
    ASSERT_EQ(vertices, expected.positions.size());
    ASSERT_TRUE(hasNormals && hasColours);
    for (size_t v = 0; v < vertices; ++v) {
        float x, y, z, nx, ny, nz;
        int r, g, b, a;
        ASSERT_TRUE(in >> x >> y >> z >> nx >> ny >> nz >> r >> g >> b >> a);
        EXPECT_NEAR(nx * nx + ny * ny + nz * nz, 1.0f, 1e-3f) << "vertex " << v;
        EXPECT_NEAR(r, vertexColours[v].r, 1.0f) << "vertex " << v;
        EXPECT_NEAR(g, vertexColours[v].g, 1.0f) << "vertex " << v;
        EXPECT_NEAR(b, vertexColours[v].b, 1.0f) << "vertex " << v;
    }
    fs::remove_all(dir);
}
