#include "atlas/pack_paper.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <queue>

namespace voxelfair {
namespace {

struct Node {
    int64_t width = 0, height = 0;
    int first = -1, second = -1;  // children; -1 for a chart (leaf)
    bool sideBySide = false;      // second to the right of first, else above it
};

// A min-heap of (size, node) with lazy deletion: merged nodes stay inside until they surface.
using Heap = std::priority_queue<std::pair<int64_t, int>, std::vector<std::pair<int64_t, int>>,
                                 std::greater<std::pair<int64_t, int>>>;

// The two smallest live nodes (they stay in the heap).
std::pair<int, int> twoSmallest(Heap &heap, const std::vector<uint8_t> &alive) {
    int found[2] = {-1, -1};
    std::pair<int64_t, int> kept[2];
    for (int k = 0; k < 2;) {
        const auto top = heap.top();
        heap.pop();
        if (!alive[size_t(top.second)])
            continue;
        found[k] = top.second;
        kept[k++] = top;
    }
    heap.push(kept[0]);
    heap.push(kept[1]);
    return {found[0], found[1]};
}

}  // namespace

int packPaper(const ChartMasks &masks, std::vector<ChartPlacement> &placements) {
    const size_t charts = masks.charts.size();
    placements.assign(charts, ChartPlacement{});
    if (charts == 0)
        return 0;
    std::vector<Node> nodes(charts);
    std::vector<uint8_t> alive(charts, 1);
    Heap byWidth, byHeight;
    for (size_t c = 0; c < charts; ++c) {
        nodes[c].width = masks.charts[c].width;
        nodes[c].height = masks.charts[c].height;
        byWidth.push({nodes[c].width, int(c)});
        byHeight.push({nodes[c].height, int(c)});
    }
    for (size_t live = charts; live > 1; --live) {
        const auto [w1, w2] = twoSmallest(byWidth, alive);
        const auto [h1, h2] = twoSmallest(byHeight, alive);
        Node across{nodes[w1].width + nodes[w2].width, std::max(nodes[w1].height, nodes[w2].height), w1, w2, true};
        Node stacked{std::max(nodes[h1].width, nodes[h2].width), nodes[h1].height + nodes[h2].height, h1, h2, false};
        auto extent = [](const Node &n) { return std::max(n.width, n.height); };
        const bool stack =
            extent(stacked) < extent(across) ||
            (extent(stacked) == extent(across) && stacked.width * stacked.height < across.width * across.height);
        const Node merged = stack ? stacked : across;
        alive[size_t(merged.first)] = alive[size_t(merged.second)] = 0;
        nodes.push_back(merged);
        alive.push_back(1);
        byWidth.push({merged.width, int(nodes.size() - 1)});
        byHeight.push({merged.height, int(nodes.size() - 1)});
    }

    // Square it, centring the shorter side, then walk the tree down to the charts.
    const Node &root = nodes.back();
    const int64_t side = std::max(root.width, root.height);
    struct Item {
        int node;
        int64_t x, y;
    };
    std::vector<Item> stack{{int(nodes.size() - 1), (side - root.width) / 2, (side - root.height) / 2}};
    while (!stack.empty()) {
        const Item it = stack.back();
        stack.pop_back();
        const Node &n = nodes[size_t(it.node)];
        if (n.first < 0) {
            placements[size_t(it.node)] = {int(it.x), int(it.y), 0};
            continue;
        }
        const Node &first = nodes[size_t(n.first)];
        stack.push_back({n.first, it.x, it.y});
        stack.push_back(
            {n.second, n.sideBySide ? it.x + first.width : it.x, n.sideBySide ? it.y : it.y + first.height});
    }
    return int(std::min<int64_t>(side, INT32_MAX));
}

}  // namespace voxelfair
