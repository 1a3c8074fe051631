// Families of analytic solids at random orientations, sizes and sub-voxel offsets (fixed seeds),
// for measuring smoothers where no single shape can be fitted: what real voxel models are made of
// (rounded hulls, armour turned at an angle, raised barrels) and shapes no issue names.
//
// Every shape has an exact signed distance (negative inside) except where noted, its exact
// volume, and bounds at positive coordinates with a margin of two voxels. Each family says which
// goal class it belongs to (FamilyGoal): smooth curved solids, cylinders and cones, boxes on the
// lattice, and shapes with flat faces and edges at an angle.
//
// Why lattice-aligned boxes have no sub-voxel offset: a face parallel to a lattice plane
// voxelizes the same wherever it lies within its voxel layer, so no method can know its offset
// (the raw surface is then the best answer, with RMS up to 0.29); a face turned away from the
// lattice shows its offset in where its steps fall. For the same reason the turned families keep
// every face at least kMinTiltDegrees away from the lattice planes (below that a 24-voxel face
// has at most one step); rounded boxes and other families at arbitrary orientation use uniformly
// random rotations with the same rule for their flat faces.
#pragma once

#include "shapes/analytic_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace voxelfair::shapes {

inline constexpr double kMinTiltDegrees = 8.0;

// ---- rotations -------------------------------------------------------------------------------

// Rotation by `angle` radians about the unit `axis` (Rodrigues).
inline glm::dmat3 rotationAbout(const glm::dvec3 &axis, double angle) {
    const glm::dvec3 a = glm::normalize(axis);
    const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
    // Columns are the images of the unit vectors.
    return glm::dmat3(glm::dvec3(t * a.x * a.x + c, t * a.x * a.y + s * a.z, t * a.x * a.z - s * a.y),
                      glm::dvec3(t * a.x * a.y - s * a.z, t * a.y * a.y + c, t * a.y * a.z + s * a.x),
                      glm::dvec3(t * a.x * a.z + s * a.y, t * a.y * a.z - s * a.x, t * a.z * a.z + c));
}

// Uniform in [0, 1), portable (std::uniform_real_distribution's algorithm is not specified).
inline double uniform01(std::mt19937_64 &random) { return double(random() >> 11) * 0x1.0p-53; }
inline double uniformIn(std::mt19937_64 &random, double lo, double hi) { return lo + (hi - lo) * uniform01(random); }

// Uniformly random rotation (Shoemake's unit quaternion).
inline glm::dmat3 randomRotation(std::mt19937_64 &random) {
    const double u1 = uniform01(random), u2 = 2.0 * kPi * uniform01(random), u3 = 2.0 * kPi * uniform01(random);
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    const double x = a * std::sin(u2), y = a * std::cos(u2), z = b * std::sin(u3), w = b * std::cos(u3);
    return glm::dmat3(glm::dvec3(1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w)),
                      glm::dvec3(2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)),
                      glm::dvec3(2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)));
}

// How far, in degrees, the plane with normal n is turned from the nearest lattice plane: the
// angle between n and the nearest lattice axis.
inline double tiltFromLattice(const glm::dvec3 &n) {
    const glm::dvec3 a = glm::abs(glm::normalize(n));
    return std::acos(std::min(1.0, std::max(a.x, std::max(a.y, a.z)))) * 180.0 / kPi;
}

// A random rotation whose images of the given local face normals are all turned at least
// kMinTiltDegrees from the lattice planes (drawn again until so).
inline glm::dmat3 randomRotationAwayFromLattice(std::mt19937_64 &random, const std::vector<glm::dvec3> &normals) {
    for (;;) {
        const glm::dmat3 r = randomRotation(random);
        bool ok = true;
        for (const glm::dvec3 &n : normals)
            ok = ok && tiltFromLattice(r * n) >= kMinTiltDegrees;
        if (ok)
            return r;
    }
}

// ---- shapes in a local frame -------------------------------------------------------------------

// `local` (an SDF around the origin with half-size `extent`) turned by `rotation` and centred at
// `centre`; bounds from the turned bounding box.
inline Shape placed(std::string name, std::function<double(const glm::dvec3 &)> local, const glm::dvec3 &extent,
                    double volume, const glm::dmat3 &rotation, const glm::dvec3 &centre) {
    Shape s;
    s.name = std::move(name);
    const glm::dmat3 inverse = glm::transpose(rotation);
    s.sdf = [local = std::move(local), inverse, centre](const glm::dvec3 &p) { return local(inverse * (p - centre)); };
    const glm::dvec3 reach =
        glm::abs(rotation[0]) * extent.x + glm::abs(rotation[1]) * extent.y + glm::abs(rotation[2]) * extent.z;
    s.boundsMin = centre - reach;
    s.boundsMax = centre + reach;
    s.volume = volume;
    return s;
}

// Moves `shape` so that its bounds start at 2 voxels plus `fraction` (a sub-voxel offset).
inline Shape atOffset(Shape shape, const glm::dvec3 &fraction) {
    const glm::dvec3 shift = glm::dvec3(2.0) + fraction - shape.boundsMin;
    auto sdf = shape.sdf;
    shape.sdf = [sdf, shift](const glm::dvec3 &p) { return sdf(p - shift); };
    shape.boundsMin += shift;
    shape.boundsMax += shift;
    return shape;
}

inline double boxDistance(const glm::dvec3 &p, const glm::dvec3 &half) {
    const glm::dvec3 q = glm::abs(p) - half;
    return glm::length(glm::max(q, 0.0)) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
}

// Box of half-size `half` with every edge and corner rounded by `radius` (<= the smallest half).
inline double roundedBoxDistance(const glm::dvec3 &p, const glm::dvec3 &half, double radius) {
    return boxDistance(p, half - radius) - radius;
}
inline double roundedBoxVolume(const glm::dvec3 &half, double r) {
    const glm::dvec3 a = 2.0 * (half - r);
    return a.x * a.y * a.z + 2.0 * r * (a.x * a.y + a.y * a.z + a.z * a.x) + kPi * r * r * (a.x + a.y + a.z) +
           4.0 / 3.0 * kPi * r * r * r;
}

// Segment a-b swept by a ball of radius r.
inline double capsuleDistance(const glm::dvec3 &p, const glm::dvec3 &a, const glm::dvec3 &b, double r) {
    const glm::dvec3 pa = p - a, ba = b - a;
    const double h = glm::clamp(glm::dot(pa, ba) / glm::dot(ba, ba), 0.0, 1.0);
    return glm::length(pa - ba * h) - r;
}

// Cone frustum around the z axis from z = -h (radius ra) to z = h (radius rb), flat caps
// (Quilez's exact capped-cone distance).
inline double frustumDistance(const glm::dvec3 &p, double h, double ra, double rb) {
    const glm::dvec2 q(std::hypot(p.x, p.y), p.z);
    const glm::dvec2 k1(rb, h), k2(rb - ra, 2.0 * h);
    const glm::dvec2 ca(q.x - std::min(q.x, q.y < 0.0 ? ra : rb), std::fabs(q.y) - h);
    const glm::dvec2 cb = q - k1 + k2 * glm::clamp(glm::dot(k1 - q, k2) / glm::dot(k2, k2), 0.0, 1.0);
    const double s = (cb.x < 0.0 && ca.y < 0.0) ? -1.0 : 1.0;
    return s * std::sqrt(std::min(glm::dot(ca, ca), glm::dot(cb, cb)));
}

// Convex polygon (counter-clockwise) in the xy plane, extruded from z = -h to h (Quilez's exact
// polygon distance and extrusion).
inline double polygonDistance2(const glm::dvec2 &p, const std::vector<glm::dvec2> &v) {
    double d = glm::dot(p - v[0], p - v[0]), s = 1.0;
    for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i, ++i) {
        const glm::dvec2 e = v[j] - v[i], w = p - v[i];
        const glm::dvec2 b = w - e * glm::clamp(glm::dot(w, e) / glm::dot(e, e), 0.0, 1.0);
        d = std::min(d, glm::dot(b, b));
        const bool c0 = p.y >= v[i].y, c1 = p.y<v[j].y, c2 = e.x * w.y> e.y * w.x;
        if ((c0 && c1 && c2) || (!c0 && !c1 && !c2))
            s = -s;
    }
    return s * std::sqrt(d);
}
inline double extrusionDistance(const glm::dvec3 &p, const std::vector<glm::dvec2> &polygon, double h) {
    const glm::dvec2 w(polygonDistance2(glm::dvec2(p.x, p.y), polygon), std::fabs(p.z) - h);
    return std::min(std::max(w.x, w.y), 0.0) + glm::length(glm::max(w, 0.0));
}
inline double polygonArea(const std::vector<glm::dvec2> &v) {
    double a = 0.0;
    for (size_t i = 0, j = v.size() - 1; i < v.size(); j = i, ++i)
        a += v[j].x * v[i].y - v[i].x * v[j].y;
    return 0.5 * a;
}

// Exact distance to the ellipsoid with semi-axes e (any order): the closest point is
// x_i = e_i^2 y_i / (t + e_i^2) for the root t > -min e_i^2 of sum (e_i y_i / (t + e_i^2))^2 = 1
// (Eberly, "Distance from a point to an ellipse, an ellipsoid, or a hyperellipsoid"), found by
// bisection in double precision.
inline double ellipsoidDistance(const glm::dvec3 &p, const glm::dvec3 &e) {
    glm::dvec3 y = glm::max(glm::abs(p), glm::dvec3(1e-12));
    const glm::dvec3 e2 = e * e;
    auto f = [&](double t) {
        const glm::dvec3 r = e * y / (t + e2);
        return glm::dot(r, r) - 1.0;
    };
    double lo = -std::min(e2.x, std::min(e2.y, e2.z)), hi = glm::length(y) * std::max(e.x, std::max(e.y, e.z));
    for (int i = 0; i < 200 && hi - lo > 1e-14 * std::max(1.0, std::fabs(hi)); ++i) {
        const double mid = 0.5 * (lo + hi);
        (f(mid) > 0.0 ? lo : hi) = mid;
    }
    const double t = 0.5 * (lo + hi);
    const glm::dvec3 x = e2 * y / (t + e2);
    const double d = glm::length(y - x);
    const glm::dvec3 q = y / e;
    return glm::dot(q, q) < 1.0 ? -d : d;
}

// ---- families ----------------------------------------------------------------------------------

// Which goal a family is held to (the smoother's tests and report read it).
enum class FamilyGoal {
    Curved,        // smooth curved solids: spheres, ellipsoids, tori, capsules
    Cylinder,      // cylinders and cones with sharp rims, at any angle
    LatticeBox,    // boxes with faces on lattice planes
    FlatAndEdges,  // flat faces and straight edges at an angle: turned boxes, rounded boxes, plates,
                   // wedges, unions
};

struct Family {
    std::string name;
    FamilyGoal goal;
    std::function<Shape(std::mt19937_64 &)> make;  // one instance, at its offset
};

struct FamilyShape {
    std::string family;
    FamilyGoal goal;
    int instance;
    Shape shape;
};

inline glm::dvec3 randomFraction(std::mt19937_64 &random) {
    return glm::dvec3(uniform01(random), uniform01(random), uniform01(random));
}

inline const glm::dvec3 kAxes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

// Face normals of a box in its own frame (enough: opposite faces are parallel).
inline std::vector<glm::dvec3> boxNormals() { return {kAxes[0], kAxes[1], kAxes[2]}; }

// About two lattice axes, one after the other (each angle away from the lattice).
inline glm::dmat3 turnAboutTwoAxes(std::mt19937_64 &random) {
    for (;;) {
        const int first = int(random() % 3), second = (first + 1 + int(random() % 2)) % 3;
        const double a = uniformIn(random, kMinTiltDegrees, 90.0 - kMinTiltDegrees) * kPi / 180.0;
        const double b = uniformIn(random, kMinTiltDegrees, 90.0 - kMinTiltDegrees) * kPi / 180.0;
        const glm::dmat3 r = rotationAbout(kAxes[second], b) * rotationAbout(kAxes[first], a);
        bool ok = true;
        for (const glm::dvec3 &n : boxNormals())
            ok = ok && tiltFromLattice(r * n) >= kMinTiltDegrees;
        if (ok)
            return r;
    }
}

inline Shape orientedBox(std::string name, const glm::dvec3 &half, const glm::dmat3 &rotation) {
    return placed(
        std::move(name), [half](const glm::dvec3 &p) { return boxDistance(p, half); }, half,
        8.0 * half.x * half.y * half.z, rotation, glm::dvec3(0.0));
}

inline Shape orientedRoundedBox(std::string name, const glm::dvec3 &half, double radius, const glm::dmat3 &rotation) {
    return placed(
        std::move(name), [half, radius](const glm::dvec3 &p) { return roundedBoxDistance(p, half, radius); }, half,
        roundedBoxVolume(half, radius), rotation, glm::dvec3(0.0));
}

// A hull (rounded box) with a barrel (capped cylinder) standing out of its top face: the barrel
// starts inside the hull, below the face's flat part, so the union's volume is the hull's plus
// the barrel's part above the face. Exact distance outside; inside, near the seam, a bound.
inline Shape barrelOnHull(std::mt19937_64 &random) {
    const glm::dvec3 half(uniformIn(random, 9, 13), uniformIn(random, 6, 9), uniformIn(random, 4, 6));
    const double fillet = uniformIn(random, 2, 3.5), barrel = uniformIn(random, 2.5, 4),
                 length = uniformIn(random, 8, 14);
    const glm::dvec3 foot(uniformIn(random, -2, 2), uniformIn(random, -1, 1), half.z - 2.0);
    const glm::dvec3 top = foot + glm::dvec3(0, 0, 2.0 + length);
    auto local = [=](const glm::dvec3 &p) {
        const glm::dvec3 w = p - foot;
        const double qr = std::hypot(w.x, w.y) - barrel,
                     qa = std::fabs(w.z - 0.5 * (top.z - foot.z)) - 0.5 * (top.z - foot.z);
        const double cylinder = std::hypot(std::max(qr, 0.0), std::max(qa, 0.0)) + std::min(std::max(qr, qa), 0.0);
        return std::min(roundedBoxDistance(p, half, fillet), cylinder);
    };
    const double volume = roundedBoxVolume(half, fillet) + kPi * barrel * barrel * length;
    const glm::dvec3 extent(half.x, half.y, std::max(half.z, top.z));
    const glm::dmat3 r = randomRotationAwayFromLattice(random, boxNormals());
    return atOffset(placed("barrel on hull", local, extent, volume, r, glm::dvec3(0.0)), randomFraction(random));
}

// The families, each drawn from its own seed so that adding one does not change the others.
inline std::vector<Family> shapeFamilies() {
    std::vector<Family> f;
    f.push_back({"sphere", FamilyGoal::Curved, [](std::mt19937_64 &g) {
                     const double r = uniformIn(g, 5, 20);
                     return atOffset(sphere(glm::dvec3(r), r), randomFraction(g));
                 }});
    f.push_back({"ellipsoid", FamilyGoal::Curved, [](std::mt19937_64 &g) {
                     const glm::dvec3 e(uniformIn(g, 6, 16), uniformIn(g, 6, 16), uniformIn(g, 5, 12));
                     auto local = [e](const glm::dvec3 &p) { return ellipsoidDistance(p, e); };
                     return atOffset(placed("ellipsoid", local, e, 4.0 / 3.0 * kPi * e.x * e.y * e.z, randomRotation(g),
                                            glm::dvec3(0.0)),
                                     randomFraction(g));
                 }});
    f.push_back({"torus", FamilyGoal::Curved, [](std::mt19937_64 &g) {
                     const double major = uniformIn(g, 9, 16), minor = uniformIn(g, 3, 6);
                     const glm::dmat3 r = randomRotation(g);
                     Shape s = torus(glm::dvec3(0.0), r[2], major, minor);
                     return atOffset(s, randomFraction(g));
                 }});
    f.push_back({"capsule", FamilyGoal::Curved, [](std::mt19937_64 &g) {
                     const double radius = uniformIn(g, 3, 7), length = uniformIn(g, 8, 24);
                     const glm::dmat3 r = randomRotation(g);
                     const glm::dvec3 a = -0.5 * length * r[2], b = 0.5 * length * r[2];
                     Shape s;
                     s.name = "capsule";
                     s.sdf = [=](const glm::dvec3 &p) { return capsuleDistance(p, a, b, radius); };
                     s.boundsMin = glm::min(a, b) - radius;
                     s.boundsMax = glm::max(a, b) + radius;
                     s.volume = kPi * radius * radius * length + 4.0 / 3.0 * kPi * radius * radius * radius;
                     return atOffset(s, randomFraction(g));
                 }});
    f.push_back({"cylinder", FamilyGoal::Cylinder, [](std::mt19937_64 &g) {
                     const double radius = uniformIn(g, 3, 7), length = uniformIn(g, 12, 30);
                     const glm::dmat3 r = randomRotationAwayFromLattice(g, {kAxes[2]});
                     Shape s = cappedCylinder(-0.5 * length * r[2], 0.5 * length * r[2], radius);
                     s.name = "cylinder";
                     return atOffset(s, randomFraction(g));
                 }});
    f.push_back({"cylinder on an axis", FamilyGoal::Cylinder, [](std::mt19937_64 &g) {
                     const double radius = uniformIn(g, 3, 7), length = double(12 + g() % 19);
                     const glm::dvec3 axis = kAxes[g() % 3];
                     // Caps on lattice planes (see the header), the round part at any offset.
                     Shape s = cappedCylinder(glm::dvec3(0.0), length * axis, radius);
                     s.name = "cylinder on an axis";
                     // (Its bounds reach `radius` past the caps along the axis too.)
                     glm::dvec3 fraction = randomFraction(g);
                     fraction += (std::ceil(radius) - radius - glm::dot(fraction, axis)) * axis;
                     return atOffset(s, fraction);
                 }});
    f.push_back({"cone", FamilyGoal::Cylinder, [](std::mt19937_64 &g) {
                     const double ra = uniformIn(g, 5, 9), rb = uniformIn(g, 2, 4), h = uniformIn(g, 5, 11);
                     auto local = [=](const glm::dvec3 &p) { return frustumDistance(p, h, ra, rb); };
                     const glm::dmat3 r = randomRotationAwayFromLattice(g, {kAxes[2]});
                     return atOffset(placed("cone", local, glm::dvec3(ra, ra, h),
                                            kPi * 2.0 * h / 3.0 * (ra * ra + ra * rb + rb * rb), r, glm::dvec3(0.0)),
                                     randomFraction(g));
                 }});
    f.push_back({"box on the lattice", FamilyGoal::LatticeBox, [](std::mt19937_64 &g) {
                     const glm::dvec3 size(double(2 + g() % 20), double(2 + g() % 20), double(2 + g() % 14));
                     return atOffset(box(0.5 * size, 0.5 * size), glm::dvec3(0.0));
                 }});
    f.push_back({"box turned about one axis", FamilyGoal::FlatAndEdges, [](std::mt19937_64 &g) {
                     // The two faces across the axis lie on lattice planes (see the header).
                     const int axis = int(g() % 3);
                     glm::dvec3 half(uniformIn(g, 4, 12), uniformIn(g, 3, 10), uniformIn(g, 3, 8));
                     half[axis] = 0.5 * double(4 + g() % 16);
                     const double angle = uniformIn(g, kMinTiltDegrees, 90.0 - kMinTiltDegrees) * kPi / 180.0;
                     glm::dvec3 fraction = randomFraction(g);
                     fraction[axis] = 0.0;
                     return atOffset(orientedBox("box turned about one axis", half, rotationAbout(kAxes[axis], angle)),
                                     fraction);
                 }});
    f.push_back({"box turned about two axes", FamilyGoal::FlatAndEdges, [](std::mt19937_64 &g) {
                     const glm::dvec3 half(uniformIn(g, 4, 12), uniformIn(g, 3, 10), uniformIn(g, 3, 8));
                     return atOffset(orientedBox("box turned about two axes", half, turnAboutTwoAxes(g)),
                                     randomFraction(g));
                 }});
    f.push_back({"rounded box", FamilyGoal::FlatAndEdges, [](std::mt19937_64 &g) {
                     const double radius = uniformIn(g, 2, 6);
                     const glm::dvec3 half(uniformIn(g, radius + 3, 14), uniformIn(g, radius + 3, 11),
                                           uniformIn(g, radius + 2, 9));
                     return atOffset(orientedRoundedBox("rounded box", half, radius,
                                                        randomRotationAwayFromLattice(g, boxNormals())),
                                     randomFraction(g));
                 }});
    f.push_back(
        {"rounded box on the lattice", FamilyGoal::FlatAndEdges, [](std::mt19937_64 &g) {
             // Flat faces on lattice planes (see the header); the fillets at any radius.
             const double radius = uniformIn(g, 2, 6);
             const glm::dvec3 size(double(int(2 * radius) + 6 + g() % 16), double(int(2 * radius) + 6 + g() % 12),
                                   double(int(2 * radius) + 4 + g() % 8));
             return atOffset(orientedRoundedBox("rounded box on the lattice", 0.5 * size, radius, glm::dmat3(1.0)),
                             glm::dvec3(0.0));
         }});
    f.push_back({"plate", FamilyGoal::FlatAndEdges, [](std::mt19937_64 &g) {
                     const glm::dvec3 half(uniformIn(g, 8, 14), uniformIn(g, 6, 12), uniformIn(g, 1.0, 2.0));
                     return atOffset(orientedBox("plate", half, randomRotationAwayFromLattice(g, boxNormals())),
                                     randomFraction(g));
                 }});
    f.push_back(
        {"wedge", FamilyGoal::FlatAndEdges, [](std::mt19937_64 &g) {
             // A right prism of a triangle with one edge at 25-60 degrees.
             const double a = uniformIn(g, 12, 22), angle = uniformIn(g, 25, 60) * kPi / 180.0, h = uniformIn(g, 4, 9);
             const std::vector<glm::dvec2> t = {{-a / 2, -a * std::tan(angle) / 4},
                                                {a / 2, -a * std::tan(angle) / 4},
                                                {-a / 2, 3 * a * std::tan(angle) / 4}};
             std::vector<glm::dvec3> normals = {kAxes[2], kAxes[1], kAxes[0], {std::sin(angle), std::cos(angle), 0.0}};
             auto local = [t, h](const glm::dvec3 &p) { return extrusionDistance(p, t, h); };
             const double reach = 3 * a * std::tan(angle) / 4;
             return atOffset(placed("wedge", local, glm::dvec3(a / 2, reach, h), polygonArea(t) * 2 * h,
                                    randomRotationAwayFromLattice(g, normals), glm::dvec3(0.0)),
                             randomFraction(g));
         }});
    f.push_back({"chamfered plate", FamilyGoal::FlatAndEdges, [](std::mt19937_64 &g) {
                     const double w = uniformIn(g, 8, 14), d = uniformIn(g, 6, 11), c = uniformIn(g, 2, 4),
                                  h = uniformIn(g, 2, 4);
                     const std::vector<glm::dvec2> o = {{-w + c, -d}, {w - c, -d}, {w, -d + c}, {w, d - c},
                                                        {w - c, d},   {-w + c, d}, {-w, d - c}, {-w, -d + c}};
                     const double s = std::sqrt(0.5);
                     std::vector<glm::dvec3> normals = {kAxes[0], kAxes[1], kAxes[2], {s, s, 0.0}, {s, -s, 0.0}};
                     auto local = [o, h](const glm::dvec3 &p) { return extrusionDistance(p, o, h); };
                     return atOffset(placed("chamfered plate", local, glm::dvec3(w, d, h), polygonArea(o) * 2 * h,
                                            randomRotationAwayFromLattice(g, normals), glm::dvec3(0.0)),
                                     randomFraction(g));
                 }});
    f.push_back({"barrel on hull", FamilyGoal::FlatAndEdges, [](std::mt19937_64 &g) { return barrelOnHull(g); }});
    return f;
}

// `perFamily` instances of each family, from `seed` (the family's index mixed in).
inline std::vector<FamilyShape> familyShapes(int perFamily, uint64_t seed = 20240915) {
    std::vector<FamilyShape> list;
    const std::vector<Family> families = shapeFamilies();
    for (size_t f = 0; f < families.size(); ++f) {
        std::mt19937_64 random(seed * 1000003u + f);
        for (int i = 0; i < perFamily; ++i) {
            Shape s = families[f].make(random);
            s.name = families[f].name + " #" + std::to_string(i);
            list.push_back({families[f].name, families[f].goal, i, std::move(s)});
        }
    }
    return list;
}

}  // namespace voxelfair::shapes
