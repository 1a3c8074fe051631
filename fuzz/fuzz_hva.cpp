// Fuzzes the HVA reader; an accepted file must hold frames x sections matrices and read back
// the same from the writer's bytes (names cut to 15 characters).
#include "formats/format_error.h"
#include "formats/hva.h"
#include "checks/surface_checks.h"

#include <string>

using namespace voxelfair;
using namespace voxelfair::fuzz;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    HvaAnimation animation;
    try {
        animation = readHva(data, size);
    } catch (const FormatError &) {
        return 0;
    }
    check(animation.frameCount >= 1 && animation.sectionCount() >= 1, "accepted an empty animation");
    check(animation.matrices.size() == size_t(animation.frameCount) * size_t(animation.sectionCount()),
          "matrix count differs from frames x sections");

    const std::vector<uint8_t> bytes = writeHva(animation);
    check(bytes.size() == size, "the writer's file differs in size");
    const HvaAnimation again = readHva(bytes.data(), bytes.size());
    for (std::string &name : animation.sectionNames)
        if (name.size() > 15)
            name.resize(15);  // the writer keeps a terminating NUL, as for VXL
    check(again.frameCount == animation.frameCount && again.sectionNames == animation.sectionNames &&
              again.matrices == animation.matrices,
          "written animation reads back different");
    return 0;
}
