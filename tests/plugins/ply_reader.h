// A small reader for the ASCII PLY files meshlabserver writes with "-m ... sa", enough to check
// what our plugins produced: vertex positions, triangle indices, face colours and face quality.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

struct PlyMesh {
    std::vector<std::array<float, 3>> positions;
    std::vector<std::array<uint32_t, 3>> triangles;
    std::vector<std::array<uint8_t, 4>> faceColours;  // empty when the file has none
    std::vector<float> faceQuality;                   // empty when the file has none
    std::vector<std::array<float, 6>> wedgeUv;        // u0 v0 u1 v1 u2 v2 per face; empty when none
    std::vector<std::string> comments;                // header comments (e.g. TextureFile)
};

// Throws std::runtime_error on anything it does not understand.
PlyMesh readAsciiPly(const std::string &path);
