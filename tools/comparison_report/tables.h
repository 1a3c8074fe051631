// The report's text: printf-style formatting, Markdown tables, the machine line.
#pragma once

#include <cstdarg>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace voxelfair::report {

inline std::string format(const char *fmt, ...) {
    char buffer[512];
    va_list args;
    va_start(args, fmt);
    std::vsnprintf(buffer, sizeof buffer, fmt, args);
    va_end(args);
    return buffer;
}

// A Markdown table: the first `textColumns` columns left-aligned, the figures right-aligned.
struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
    size_t textColumns = 1;

    std::string markdown() const {
        std::ostringstream out;
        auto line = [&out](const std::vector<std::string> &cells) {
            out << "|";
            for (const std::string &c : cells)
                out << " " << c << " |";
            out << "\n";
        };
        line(header);
        out << "|";
        for (size_t i = 0; i < header.size(); ++i)
            out << (i < textColumns ? "---|" : "---:|");
        out << "\n";
        for (const auto &row : rows)
            line(row);
        return out.str();
    }
};

// Milliseconds with 2 decimals below 10, 1 above.
inline std::string ms(double v) { return v < 10 ? format("%.2f", v) : format("%.1f", v); }

// The CPU, its threads and the load average: other work on the machine slows the timings down.
std::string machine();

}  // namespace voxelfair::report
