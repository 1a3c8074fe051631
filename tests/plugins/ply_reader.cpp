#include "ply_reader.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace {

struct Element {
    std::string name;
    size_t count = 0;
    std::vector<std::string> properties;  // a list property is stored as "list:<name>"
};

}  // namespace

PlyMesh readAsciiPly(const std::string &path) {
    std::ifstream in(path);
    if (!in)
        throw std::runtime_error(path + ": cannot open");
    std::string line;
    std::getline(in, line);
    if (line.rfind("ply", 0) != 0)
        throw std::runtime_error(path + ": not a PLY file");

    PlyMesh mesh;
    std::vector<Element> elements;
    while (std::getline(in, line) && line.rfind("end_header", 0) != 0) {
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "format" && line.find("ascii") == std::string::npos)
            throw std::runtime_error(path + ": not ASCII (save with -m ... sa)");
        if (keyword == "comment")
            mesh.comments.push_back(line.substr(8));
        if (keyword == "element") {
            Element e;
            words >> e.name >> e.count;
            elements.push_back(e);
        }
        if (keyword == "property" && !elements.empty()) {
            std::string type, name;
            words >> type;
            if (type == "list") {
                std::string countType, itemType;
                words >> countType >> itemType >> name;
                name = "list:" + name;
            } else {
                words >> name;
            }
            elements.back().properties.push_back(name);
        }
    }
    for (const Element &e : elements) {
        for (size_t i = 0; i < e.count; ++i) {
            if (!std::getline(in, line))
                throw std::runtime_error(path + ": truncated " + e.name + " list");
            std::istringstream values(line);
            std::array<float, 3> p{};
            std::array<uint8_t, 4> colour{0, 0, 0, 255};
            bool hasColour = false;
            for (const std::string &prop : e.properties) {
                if (prop == "list:texcoord") {
                    size_t n = 0;
                    values >> n;
                    if (n != 6)
                        throw std::runtime_error(path + ": a face has " + std::to_string(n) + " texcoords");
                    std::array<float, 6> uv{};
                    for (float &x : uv)
                        values >> x;
                    mesh.wedgeUv.push_back(uv);
                    continue;
                }
                if (prop.rfind("list:", 0) == 0) {
                    size_t n = 0;
                    values >> n;
                    std::vector<uint32_t> idx(n);
                    for (auto &v : idx)
                        values >> v;
                    if (e.name == "face") {
                        if (n != 3)
                            throw std::runtime_error(path + ": a face is not a triangle");
                        mesh.triangles.push_back({idx[0], idx[1], idx[2]});
                    }
                    continue;
                }
                // strtod, unlike >>, reads "nan" and "inf" as MeshLab writes them.
                std::string token;
                values >> token;
                char *end = nullptr;
                const double v = std::strtod(token.c_str(), &end);
                if (token.empty() || *end != '\0')
                    values.setstate(std::ios::failbit);
                if (e.name == "vertex") {
                    if (prop == "x")
                        p[0] = float(v);
                    if (prop == "y")
                        p[1] = float(v);
                    if (prop == "z")
                        p[2] = float(v);
                } else if (e.name == "face") {
                    if (prop == "red")
                        colour[0] = uint8_t(v), hasColour = true;
                    if (prop == "green")
                        colour[1] = uint8_t(v);
                    if (prop == "blue")
                        colour[2] = uint8_t(v);
                    if (prop == "alpha")
                        colour[3] = uint8_t(v);
                    if (prop == "quality")
                        mesh.faceQuality.push_back(float(v));
                }
            }
            if (!values)
                throw std::runtime_error(path + ": bad " + e.name + " line: " + line);
            if (e.name == "vertex")
                mesh.positions.push_back(p);
            if (e.name == "face" && hasColour)
                mesh.faceColours.push_back(colour);
        }
    }
    return mesh;
}
