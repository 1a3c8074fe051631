// MikkTSpace tangents: the tangent basis glTF 2.0, Blender, Unity, Unreal and Godot agree on, so
// a normal map baked against it shades the same in all of them. Written from Morten S.
// Mikkelsen's master thesis "Simulation of Wrinkled Surfaces Revisited" (2008) and the
// conventions of his reference implementation (mikktspace.c, genTangSpaceDefault):
//
//   * corners with bit-identical position, normal and texture coordinate are one vertex;
//   * a triangle with two equal positions is degenerate: its corners copy the space of the first
//     healthy corner of the same vertex, or keep the default (1, 0, 0), sign -1;
//   * per triangle, the first-order derivatives dP/ds, dP/dt (thesis eq. 18, 19), normalised and
//     flipped with the sign of the UV area; a triangle with zero UV area or a zero derivative
//     "groups with anything" and takes the orientation of the first group that reaches it;
//   * corners of one vertex join a group through triangles sharing an edge of that vertex and
//     of the same orientation (the reference's four rules); a group is split only where two
//     projected derivatives are exactly opposite (default angular threshold 180 degrees);
//   * a group's tangent is the corner-angle weighted mean of its triangles' dP/ds projected onto
//     the vertex normal; the sign (+1 / -1) is the group's orientation (bitangent = sign *
//     cross(normal, tangent)).
//
// Input is per corner, three corners per triangle, like the reference's interface; the normals
// are expected to be unit length. Tested against the npm package `mikktspace` (a WebAssembly
// build of the reference) on real faired meshes.
#pragma once

#include <cstddef>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace voxelfair {

struct TangentInput {
    // 3 * triangleCount corners each.
    const glm::vec3 *positions = nullptr;
    const glm::vec3 *normals = nullptr;
    const glm::vec2 *uvs = nullptr;
    size_t triangleCount = 0;
};

// One tangent per corner: xyz unit length (or the default (1, 0, 0)), w the bitangent sign.
std::vector<glm::vec4> computeMikkTSpaceTangents(const TangentInput &input);

}  // namespace voxelfair
