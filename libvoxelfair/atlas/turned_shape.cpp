#include "atlas/turned_shape.h"

#include "base/byte_words.h"

#include <algorithm>
#include <cstddef>
#include <cstring>

namespace voxelfair {
namespace {

// s.spans longest first, equal lengths in the order they came: the order std::stable_sort gives,
// by counting lengths when there are many spans of few lengths (a large chart's rows), as they
// are when they already are in order (a box's spans, all of one length).
void sortSpans(TurnedShape &s) {
    std::vector<ShapeSpan> &spans = s.spans;
    const auto longer = [](const ShapeSpan &a, const ShapeSpan &b) { return a.length > b.length; };
    if (std::is_sorted(spans.begin(), spans.end(), longer))
        return;
    int least = INT16_MAX, most = INT16_MIN;
    for (const ShapeSpan &sp : spans)
        least = std::min<int>(least, sp.length), most = std::max<int>(most, sp.length);
    if (spans.size() < 32 || size_t(most - least) > 4 * spans.size()) {
        std::stable_sort(spans.begin(), spans.end(), longer);
        return;
    }
    s.starts.assign(size_t(most - least) + 2, 0);  // bucket most - length, from the longest
    for (const ShapeSpan &sp : spans)
        ++s.starts[size_t(most - sp.length) + 1];
    for (size_t b = 1; b < s.starts.size(); ++b)
        s.starts[b] += s.starts[b - 1];
    s.sorted.resize(spans.size());
    for (const ShapeSpan &sp : spans)
        s.sorted[size_t(s.starts[size_t(most - sp.length)]++)] = sp;
    spans.swap(s.sorted);
}

// The first c in [from, right] where the bitmap byte row[c * stride] (0 or 1) is set (`set`) or
// not, right + 1 if none. Along a stored row (stride 1 or -1) eight bytes at a time.
int nextByte(const uint8_t *row, ptrdiff_t stride, int from, int right, bool set) {
    const uint64_t flip = set ? 0 : kAllBytesOne;  // set bytes of the word: the ones sought
    int c = from;
    if (stride == 1) {
        for (; c + 8 <= right + 1; c += 8) {
            uint64_t v;
            std::memcpy(&v, row + c, 8);
            if ((v ^= flip) != 0)
                return c + lowestSetByte(v);
        }
    } else if (stride == -1) {  // c runs down through memory: the word ending at row - c
        for (; c + 8 <= right + 1; c += 8) {
            uint64_t v;
            std::memcpy(&v, row - c - 7, 8);
            if ((v ^= flip) != 0)
                return c + 7 - highestSetByte(v);
        }
    }
    while (c <= right && (row[c * stride] != 0) != set)
        ++c;
    return c;
}

}  // namespace

// Found in one pass over the rows, eight bytes at a time, where a row differs from the one below
// it (start[x]: where column x's open run began), then ordered by column.
void findColumnRuns(const uint8_t *bits, int w, int h, ColumnRuns &out) {
    out.found.clear();
    out.start.assign(size_t(w), 0);
    const size_t words = (size_t(w) + 7) / 8;
    out.below.assign(words, 0);  // the row below's words (none below row 0)
    for (int y = 0; y <= h; ++y)
        for (size_t k = 0; k < words; ++k) {
            // None above the top row; the last word padded with zeros.
            const uint64_t now = y < h ? byteWord(bits + size_t(y) * size_t(w), size_t(w), k) : 0;
            const uint64_t changed0 = now ^ out.below[k];
            out.below[k] = now;
            for (uint64_t changed = changed0; changed != 0; changed &= changed - 1) {
                const int byte = lowestSetByte(changed);
                const size_t x = 8 * k + size_t(byte);
                if (now >> (8 * byte) & 1)
                    out.start[x] = int16_t(y);
                else
                    out.found.push_back({int16_t(x), out.start[x], int16_t(y - out.start[x])});
            }
        }
    // By column, each column's runs in the order found (upwards).
    out.first.assign(size_t(w) + 1, 0);
    for (const ColumnRuns::Run &r : out.found)
        ++out.first[size_t(r.column) + 1];
    for (int x = 0; x < w; ++x)
        out.first[size_t(x) + 1] += out.first[size_t(x)];
    out.runs.resize(out.found.size());
    std::vector<int> &at = out.first;  // advanced while filling, then moved back
    for (const ColumnRuns::Run &r : out.found)
        out.runs[size_t(at[size_t(r.column)]++)] = r;
    for (int x = w; x > 0; --x)
        at[size_t(x)] = at[size_t(x) - 1];
    at[0] = 0;
}

void turnedShape(const ChartMask &m, const std::vector<int16_t> &profiles, int turns, bool box, const uint8_t *bits,
                 const ColumnRuns *columns, TurnedShape &s) {
    const int16_t *colBottom = m.colBottom(profiles), *colTop = m.colTop(profiles);
    const int16_t *rowLeft = m.rowLeft(profiles), *rowRight = m.rowRight(profiles);
    const int w = m.width, h = m.height;
    s.width = turns & 1 ? h : w;
    s.height = turns & 1 ? w : h;
    s.left.resize(size_t(s.height));
    s.right.resize(size_t(s.height));
    for (int r = 0; r < s.height; ++r) {
        int16_t &left = s.left[size_t(r)], &right = s.right[size_t(r)];
        if (box) {
            left = 0, right = int16_t(s.width - 1);
            continue;
        }
        switch (turns) {
        case 0: left = rowLeft[r], right = rowRight[r]; break;
        case 1: left = int16_t(h - 1 - colTop[r]), right = int16_t(h - 1 - colBottom[r]); break;
        case 2: left = int16_t(w - 1 - rowRight[h - 1 - r]), right = int16_t(w - 1 - rowLeft[h - 1 - r]); break;
        default: left = colBottom[w - 1 - r], right = colTop[w - 1 - r]; break;
        }
    }
    s.spans.clear();
    if (box || bits == nullptr) {
        for (int r = 0; r < s.height; ++r)
            s.spans.push_back({int16_t(r), s.left[size_t(r)], int16_t(s.right[size_t(r)] - s.left[size_t(r)] + 1)});
    } else if (turns & 1 && columns) {
        // Row r is the bitmap's column r read downwards (one turn) or column w - 1 - r upwards
        // (three turns): its runs, in the order of the turned row.
        for (int r = 0; r < s.height; ++r) {
            const int x = turns == 1 ? r : w - 1 - r;
            const int from = columns->first[size_t(x)], to = columns->first[size_t(x) + 1];
            if (turns == 3) {
                for (int i = from; i < to; ++i) {
                    const ColumnRuns::Run &run = columns->runs[size_t(i)];
                    s.spans.push_back({int16_t(r), run.bottom, run.length});
                }
            } else {
                for (int i = to - 1; i >= from; --i) {
                    const ColumnRuns::Run &run = columns->runs[size_t(i)];
                    s.spans.push_back({int16_t(r), int16_t(h - run.bottom - run.length), run.length});
                }
            }
        }
    } else {
        // The bitmap read through the turn (the profiles' mapping above, texel by texel): row r
        // of the turned shape starts at bits[origin(r)] and steps by `stride` per column.
        ptrdiff_t stride = 1;
        auto origin = [&](int r) -> ptrdiff_t {
            switch (turns) {
            case 0: return ptrdiff_t(r) * w;
            case 1: return ptrdiff_t(h - 1) * w + r;
            case 2: return ptrdiff_t(h - 1 - r) * w + (w - 1);
            default: return w - 1 - r;
            }
        };
        switch (turns) {
        case 0: stride = 1; break;
        case 1: stride = -w; break;
        case 2: stride = -1; break;
        default: stride = w; break;
        }
        for (int r = 0; r < s.height; ++r) {
            const uint8_t *row = bits + origin(r);
            const int right = s.right[size_t(r)];
            for (int c = s.left[size_t(r)]; c <= right;) {
                c = nextByte(row, stride, c, right, true);
                if (c > right)
                    break;
                const int start = c;
                c = nextByte(row, stride, c, right, false);
                s.spans.push_back({int16_t(r), int16_t(start), int16_t(c - start)});
            }
        }
    }
    sortSpans(s);
    s.need.assign(size_t(s.height), 0);
    s.needRows.clear();
    for (const ShapeSpan &sp : s.spans)
        if (s.need[size_t(sp.row)] == 0) {
            s.need[size_t(sp.row)] = sp.length;
            s.needRows.push_back(sp.row);
        }
}

}  // namespace voxelfair
