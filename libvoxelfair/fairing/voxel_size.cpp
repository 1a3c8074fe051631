#include "fairing/voxel_size.h"

#include "base/parallel_bands.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

namespace voxelfair {

float detectVoxelSize(const PolygonMesh &mesh, float expected, int threads) {
    const glm::vec3 *const positions = mesh.positions;
    const size_t vertexCount = mesh.vertexCount, polygonCount = mesh.polygonCount;
    const uint32_t *const polygonOffsets = mesh.polygonOffsets, *const polygonIndices = mesh.polygonIndices;
    constexpr size_t kMaxEdges = size_t(1) << 16;
    if (!positions || !polygonOffsets || !polygonIndices || polygonCount == 0)
        return 0.0f;
    const size_t indexCount = polygonOffsets[polygonCount];
    const size_t stride = std::max<size_t>(1, indexCount / kMaxEdges);  // ~one edge per index

    // (bin, length): bin = round(log(length) / log(1 + 1e-3)), i.e. 1e-3 relative bins.
    const double binsPerLog = 1.0 / std::log1p(1e-3);
    // Sampled polygons p = j * stride, j < samples, measured in bands of j on up to `threads`
    // threads, each band's lengths in its own list, joined in band order: the list of one scan.
    const size_t samples = (polygonCount + stride - 1) / stride;
    constexpr size_t kLeastBandSamples = size_t(1) << 13;
    const size_t bands = size_t(bandThreads(threads, std::max<size_t>(1, samples / kLeastBandSamples)));
    std::vector<std::vector<std::pair<long, float>>> bandLengths(bands);
    runBands(bands, int(bands), [&](size_t band) {
        std::vector<std::pair<long, float>> &lengths = bandLengths[band];
        lengths.reserve(std::min(indexCount, 2 * kMaxEdges) / bands + 64);
        // A voxel mesh's edges mostly repeat one length exactly (the voxel's, before fairing): the
        // last length's bin is kept, so the logarithm is taken when the length changes.
        float lastLength = 0.0f;
        long lastBin = 0;
        for (size_t j = samples * band / bands; j < samples * (band + 1) / bands; ++j) {
            const size_t p = j * stride;
            const uint32_t first = polygonOffsets[p], last = polygonOffsets[p + 1];
            if (last <= first + 1 || last > indexCount)
                continue;
            for (uint32_t i = first; i < last; ++i) {
                const uint32_t a = polygonIndices[i];
                const uint32_t b = polygonIndices[i + 1 < last ? i + 1 : first];
                if (a >= vertexCount || b >= vertexCount)
                    continue;
                const float length = glm::length(positions[b] - positions[a]);
                if (!(length > 0.0f) || !std::isfinite(length))
                    continue;
                if (length != lastLength) {
                    lastLength = length;
                    lastBin = std::lround(std::log(double(length)) * binsPerLog);
                }
                lengths.emplace_back(lastBin, length);
            }
        }
    });
    std::vector<std::pair<long, float>> lengths = std::move(bandLengths[0]);
    for (size_t band = 1; band < bands; ++band)
        lengths.insert(lengths.end(), bandLengths[band].begin(), bandLengths[band].end());
    if (lengths.empty())
        return 0.0f;
    if (expected > 0.0f && std::isfinite(expected)) {
        const long bin = std::lround(std::log(double(expected)) * binsPerLog);
        const size_t kept =
            size_t(std::count_if(lengths.begin(), lengths.end(),
                                 [bin](const std::pair<long, float> &l) { return std::abs(l.first - bin) <= 1; }));
        if (20 * kept >= lengths.size())
            return expected;
    }

    // The most common bin (the lowest among equals), counted in an array over the bins' range:
    // finite positive floats span ln(FLT_MAX / FLT_TRUE_MIN) / ln(1.001), about 192k bins, so the
    // array stays under 1 MB whatever the lengths (a mesh's span a few binades).
    long least = lengths[0].first, most = least;
    for (const auto &l : lengths)
        least = std::min(least, l.first), most = std::max(most, l.first);
    std::vector<uint32_t> counts(size_t(most - least) + 1, 0);
    for (const auto &l : lengths)
        ++counts[size_t(l.first - least)];
    long bestBin = least;
    size_t bestCount = 0;
    for (size_t b = 0; b < counts.size(); ++b)
        if (counts[b] > bestCount) {
            bestCount = counts[b];
            bestBin = least + long(b);
        }
    // The bin's mean length. Its lengths lie within 0.1% of each other (one binade or two
    // adjacent ones) and are far fewer than 2^28 floats, so their sum in double is exact in any
    // order.
    double sum = 0.0;
    for (const auto &l : lengths)
        if (l.first == bestBin)
            sum += l.second;
    return float(sum / double(bestCount));
}

}  // namespace voxelfair
