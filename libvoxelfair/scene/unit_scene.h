// A whole Tiberian Sun / Red Alert 2 vehicle: the body NAME.vxl with NAMEtur.vxl (turret) and
// NAMEbarl.vxl (barrel), each with its own .hva, placed together as the game draws them
// (ModEnc: "Voxel Turret and Barrel Positioning", "TurretOffset"): every file's sections by its
// own HVA; turret and barrel moved by the art rules' TurretOffset along the unit's forward axis
// (+x). The offset is in leptons and is not in the files; it is turned into voxels with the
// body's section scale ("Det", 1/12 in Westwood's files), the factor that turns HVA translations
// (leptons) into voxels.
//
// Besides the scene to mesh, it describes the parts for exporters (export/export_scene.h): a
// node per file (body, turret, barrel; the barrel under the turret, so turning the turret turns
// the barrel) with its pivot at the file's rotation origin, and a child node per section at the
// section's rotation frame; an .hva with several frames animates its sections.
#pragma once

#include "export/export_scene.h"
#include "formats/hva.h"
#include "formats/vxl.h"
#include "scene/voxel_scene.h"
#include "scene/vxl_scene.h"

#include <optional>
#include <string>
#include <vector>

namespace voxelfair {

enum class UnitRole { Body, Turret, Barrel };

struct UnitFile {
    UnitRole role = UnitRole::Body;
    std::string name;  // for node names and messages, e.g. "3tnktur.vxl"
    VxlModel model;
    std::optional<HvaAnimation> hva;
};

// "body", "turret", "barrel".
const char *unitRoleName(UnitRole role);

// The companion of a body file stem ("3tnk" -> "3tnktur" / "3tnkbarl").
std::string unitCompanionStem(const std::string &bodyStem, UnitRole role);

// True when a file stem names a turret or barrel file (ends in "tur" or "barl", any case), which
// is never a body of its own unit.
bool isUnitCompanionStem(const std::string &stem);

struct UnitSceneOptions {
    VxlSceneOptions vxl;               // palette, house colour, frame, transforms; section must be -1
    float turretOffsetLeptons = 0.0f;  // TurretOffset of the unit's art rules
};

struct UnitScene {
    VoxelScene scene;  // parts numbered through the files: body sections first, then turret, barrel
    ExportScene nodes;
    std::vector<size_t> sectionsPerFile;
};

// `files[0]` is the body; the others follow in any order. The frame is clamped to each file's
// .hva (a one-frame turret stays put while the body's .hva plays). The scene points into the
// files' models: keep them alive with it. Throws FormatError as vxlScene does, naming the file.
UnitScene unitScene(const std::vector<UnitFile> &files, const UnitSceneOptions &options);

}  // namespace voxelfair
