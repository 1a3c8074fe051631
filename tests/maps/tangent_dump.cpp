// Writes MikkTSpace inputs and our tangents for real faired meshes (undecimated, and decimated to
// 10% with MeshLab's decimation when vcglib is there), for mikktspace_reference.mjs to compare
// with the reference (npm `mikktspace`). One file per mesh in OUTDIR: uint32 corner count, then
// float32 positions (3 per corner), normals (3), UVs (2), our tangents (4).
//
//   maps_tangent_dump OUTDIR MODEL...
#include "pipeline/faired_models.h"
#include "maps/mikktspace.h"

#include <cstdio>
#include <fstream>

using namespace voxelfair;
using namespace voxelfair::mapstest;

namespace {
void write(const std::string &path, const std::vector<glm::vec3> &positions, const std::vector<glm::vec3> &normals,
           const std::vector<uint32_t> &triangles, const std::vector<glm::vec2> &wedgeUv) {
    const size_t corners = triangles.size();
    std::vector<glm::vec3> p(corners), n(corners);
    for (size_t c = 0; c < corners; ++c) {
        p[c] = positions[triangles[c]];
        n[c] = glm::normalize(normals[triangles[c]]);
    }
    TangentInput in;
    in.positions = p.data();
    in.normals = n.data();
    in.uvs = wedgeUv.data();
    in.triangleCount = corners / 3;
    const std::vector<glm::vec4> t = computeMikkTSpaceTangents(in);
    std::ofstream out(path, std::ios::binary);
    const uint32_t count = uint32_t(corners);
    out.write(reinterpret_cast<const char *>(&count), 4);
    out.write(reinterpret_cast<const char *>(p.data()), std::streamsize(corners * sizeof(glm::vec3)));
    out.write(reinterpret_cast<const char *>(n.data()), std::streamsize(corners * sizeof(glm::vec3)));
    out.write(reinterpret_cast<const char *>(wedgeUv.data()), std::streamsize(corners * sizeof(glm::vec2)));
    out.write(reinterpret_cast<const char *>(t.data()), std::streamsize(corners * sizeof(glm::vec4)));
    std::printf("%s: %zu triangles\n", path.c_str(), corners / 3);
}
}  // namespace

int main(int argc, char **argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: maps_tangent_dump OUTDIR MODEL...\n");
        return 2;
    }
    const std::filesystem::path dir = argv[1];
    std::filesystem::create_directories(dir);
    for (int i = 2; i < argc; ++i) {
        const std::filesystem::path file = argv[i];
        std::unique_ptr<pipeline::Model> model;
        try {
            model = file.extension() == ".vxl"
                        ? pipeline::loadVxl(file.string(), (file.parent_path().parent_path() / "pal").string())
                        : pipeline::loadVox(file.string());
        } catch (const std::exception &e) {
            std::fprintf(stderr, "%s: %s\n", file.string().c_str(), e.what());
            return 1;
        }
        const FairedMesh hi = fairedMesh(*model, 8.0f);
        write((dir / (model->name + "_faired.bin")).string(), hi.positions, hi.normals, hi.triangles, hi.wedgeUv);
#ifdef VOXELFAIR_HAVE_VCGLIB
        const vcgdecimate::TexturedMesh lo = vcgdecimate::decimate(hi.positions, hi.triangles, hi.wedgeUv, 0.1);
        write((dir / (model->name + "_decimated.bin")).string(), lo.positions, lo.normals, lo.triangles, lo.wedgeUv);
#endif
    }
    return 0;
}
