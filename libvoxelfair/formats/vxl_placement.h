// Where a VXL section sits in the model: section voxel space -> model space.
#pragma once

#include "formats/vxl.h"

#include <glm/mat4x4.hpp>

namespace voxelfair {

// The affine map of the editor the paper's authors wrote (VXLSE; doc/formats/westwood.md §8):
//   p_model = R * (minBounds + v * voxelScale) + t * scale
// where (R | t) is the section's HVA matrix for the chosen frame. Without an HVA (`hvaMatrix`
// null) the tailer matrix is used as stored, its translation being already scaled.
glm::mat4 sectionToModel(const VxlSection &section, const Matrix3x4 *hvaMatrix);

// The section's rotation frame, (R | t * scale): the origin the game turns the section about.
// sectionToModel = sectionPivotToModel * translate(minBounds) * scale(voxelScale).
glm::mat4 sectionPivotToModel(const VxlSection &section, const Matrix3x4 *hvaMatrix);

}  // namespace voxelfair
