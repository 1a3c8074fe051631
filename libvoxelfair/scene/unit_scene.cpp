// See unit_scene.h.
#include "scene/unit_scene.h"

#include "formats/format_error.h"
#include "formats/vxl_placement.h"

#include <algorithm>
#include <cctype>

#include <glm/gtc/matrix_transform.hpp>

namespace voxelfair {

namespace {

bool endsWithNoCase(const std::string &text, const std::string &suffix) {
    if (text.size() < suffix.size())
        return false;
    for (size_t i = 0; i < suffix.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(text[text.size() - suffix.size() + i])) != suffix[i])
            return false;
    return true;
}

}  // namespace

const char *unitRoleName(UnitRole role) {
    switch (role) {
    case UnitRole::Body: return "body";
    case UnitRole::Turret: return "turret";
    case UnitRole::Barrel: return "barrel";
    }
    return "part";
}

std::string unitCompanionStem(const std::string &bodyStem, UnitRole role) {
    if (role == UnitRole::Body)
        return bodyStem;
    return bodyStem + (role == UnitRole::Turret ? "tur" : "barl");
}

bool isUnitCompanionStem(const std::string &stem) {
    return (stem.size() > 3 && endsWithNoCase(stem, "tur")) || (stem.size() > 4 && endsWithNoCase(stem, "barl"));
}

UnitScene unitScene(const std::vector<UnitFile> &files, const UnitSceneOptions &options) {
    if (files.empty() || files[0].role != UnitRole::Body)
        throw FormatError("a unit needs its body file first");
    if (options.vxl.section != -1)
        throw FormatError("a unit is imported with all its sections");
    UnitScene unit;
    unit.nodes.front = ModelFront::PlusX;

    // Leptons -> voxels with the body's Det (HVA translations are leptons scaled by it).
    const VxlModel &body = files[0].model;
    const float det = body.sections.empty() ? 1.0f / 12.0f : body.sections[0].scale;
    const glm::mat4 turretPlace =
        glm::translate(glm::mat4(1.0f), glm::vec3(options.turretOffsetLeptons * det, 0.0f, 0.0f));

    size_t frames = 1;
    for (const UnitFile &file : files)
        if (options.vxl.applyTransforms && file.hva)
            frames = std::max(frames, size_t(file.hva->frameCount));

    int turretNode = -1;
    for (size_t f = 0; f < files.size(); ++f) {
        const UnitFile &file = files[f];
        VxlSceneOptions o = options.vxl;
        if (file.hva && f > 0)
            o.frame = std::min(o.frame, file.hva->frameCount - 1);
        VoxelScene placed;
        try {
            placed = vxlScene(file.model, file.hva ? &*file.hva : nullptr, o);
        } catch (const FormatError &e) {
            throw FormatError(file.name + ": " + e.what());
        }
        if (f == 0)
            unit.scene.palette = placed.palette;

        const glm::mat4 fileWorld = file.role == UnitRole::Body ? glm::mat4(1.0f) : turretPlace;
        ExportNode fileNode;
        fileNode.name = unitRoleName(file.role);
        fileNode.parent = file.role == UnitRole::Barrel ? turretNode : -1;
        fileNode.world = fileWorld;
        const int fileIndex = int(unit.nodes.nodes.size());
        if (file.role == UnitRole::Turret)
            turretNode = fileIndex;
        unit.nodes.nodes.push_back(fileNode);

        const int firstPart = int(unit.scene.parts.size());
        for (size_t s = 0; s < placed.parts.size(); ++s) {
            PlacedVolume part = placed.parts[s];
            const VxlSection &section = file.model.sections[size_t(part.part)];
            part.toModel = fileWorld * part.toModel;
            part.part = firstPart + int(s);
            unit.scene.parts.push_back(part);

            ExportNode node;
            node.name = files.size() > 1 ? std::string(unitRoleName(file.role)) + "_" + section.name : section.name;
            node.parent = fileIndex;
            const auto pivotAt = [&](int frame) {
                if (!options.vxl.applyTransforms)
                    return fileWorld;
                const Matrix3x4 *m = file.hva ? &file.hva->matrix(std::min(frame, file.hva->frameCount - 1),
                                                                  int(&section - file.model.sections.data()))
                                              : nullptr;
                return fileWorld * sectionPivotToModel(section, m);
            };
            node.world = pivotAt(o.frame);
            if (options.vxl.applyTransforms && file.hva && file.hva->frameCount > 1)
                for (size_t k = 0; k < frames; ++k)
                    node.frames.push_back(pivotAt(int(k)));
            unit.nodes.partNodes.push_back(int(unit.nodes.nodes.size()));
            unit.nodes.nodes.push_back(node);
        }
        unit.sectionsPerFile.push_back(placed.parts.size());
    }
    // Static nodes under a moving one need no frames; moving ones all have `frames`.
    return unit;
}

}  // namespace voxelfair
