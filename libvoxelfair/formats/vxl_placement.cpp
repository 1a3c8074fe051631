#include "formats/vxl_placement.h"

#include <cmath>

namespace voxelfair {

glm::vec3 VxlSection::voxelScale() const {
    const int size[3] = {volume.sizeX, volume.sizeY, volume.sizeZ};
    glm::vec3 scale(1.0f);
    for (int a = 0; a < 3; ++a) {
        const float s = size[a] > 0 ? (maxBounds[a] - minBounds[a]) / float(size[a]) : 0.0f;
        if (std::isfinite(s) && s > 0.0f)
            scale[a] = s;
    }
    return scale;
}

glm::mat4 sectionToModel(const VxlSection &section, const Matrix3x4 *hvaMatrix) {
    // The tailer's translation is already multiplied by the section scale; the HVA's is not.
    const Matrix3x4 &m = hvaMatrix ? *hvaMatrix : section.transform;
    const float translationScale = hvaMatrix ? section.scale : 1.0f;
    const glm::vec3 sf = section.voxelScale();

    // p = R * (minBounds + v * sf) + t * scale = (R * diag(sf)) v + (R * minBounds + t * scale).
    glm::mat4 result(1.0f);  // glm is column-major: result[column][row]
    for (int row = 0; row < 3; ++row) {
        float translation = m[size_t(row) * 4 + 3] * translationScale;
        for (int col = 0; col < 3; ++col) {
            const float r = m[size_t(row) * 4 + size_t(col)];
            result[col][row] = r * sf[col];
            translation += r * section.minBounds[col];
        }
        result[3][row] = translation;
    }
    return result;
}

glm::mat4 sectionPivotToModel(const VxlSection &section, const Matrix3x4 *hvaMatrix) {
    const Matrix3x4 &m = hvaMatrix ? *hvaMatrix : section.transform;
    const float translationScale = hvaMatrix ? section.scale : 1.0f;
    glm::mat4 result(1.0f);
    for (int row = 0; row < 3; ++row) {
        for (int col = 0; col < 3; ++col)
            result[col][row] = m[size_t(row) * 4 + size_t(col)];
        result[3][row] = m[size_t(row) * 4 + 3] * translationScale;
    }
    return result;
}

}  // namespace voxelfair
