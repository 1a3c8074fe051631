// Fuzzes the VXL reader, then what the importer does with an accepted file: the writer's bytes
// must read back to the same model, and the placed sections must mesh to closed, consistently
// oriented manifolds.
#include "fixtures/vxl_fixtures.h"
#include "formats/format_error.h"
#include "formats/vxl.h"
#include "scene/vxl_scene.h"
#include "checks/surface_checks.h"

using namespace voxelfair;
using namespace voxelfair::fuzz;

namespace {

// The writer cuts names to 15 characters; everything else reads back as it was.
void checkRoundTrip(VxlModel model) {
    const std::vector<uint8_t> bytes = writeVxl(model);
    VxlModel again;
    try {
        again = readVxl(bytes.data(), bytes.size());
    } catch (const FormatError &e) {
        fail("the writer's bytes do not read back: %s", e.what());
    }
    for (VxlSection &section : model.sections) {
        if (section.name.size() > 15)
            section.name.resize(15);
        section.clampedNormals = 0;  // the clamped indices are written, and read back unclamped
    }
    const std::string difference = fixtures::firstDifference(model, again);
    if (!difference.empty())
        fail("written model reads back different: %s", difference.c_str());
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    VxlModel model;
    try {
        model = readVxl(data, size);
    } catch (const FormatError &) {
        return 0;
    }
    checkRoundTrip(model);

    // Voxels are capped at one per two bytes, so meshing stays proportional to the input.
    const SceneSurface surface = extractSceneSurface(vxlScene(model, nullptr, VxlSceneOptions{}));
    checkClosedManifold(surface.quads, surface.positions.size());
    return 0;
}
