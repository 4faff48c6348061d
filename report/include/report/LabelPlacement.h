// LabelPlacement: where the labels of a scatter plot go so that none covers another, a marker, or leaves
// the plot (the error-vs-time plot of `shadowfx bench`, whose points cluster when runs differ little).
//
// Greedy, in the order of the points: each label takes the first free spot of a ring of candidates around its
// point, nearest ring first; a spot beyond the first ring gets a leader line to its point. A label with no
// free spot falls back to its number (1-based, in the order given), placed the same way, and to the plot's
// table of numbered labels; a number that finds no spot either stays only in that table.
#pragma once

#include <string>
#include <vector>

namespace report {

struct Box {
    double x = 0, y = 0, width = 0, height = 0;  // top-left corner, in pixels (y down)

    bool overlaps(const Box& other) const {
        return x < other.x + other.width && other.x < x + width && y < other.y + other.height &&
               other.y < y + height;
    }
};

struct PlacedLabel {
    enum class Kind { Text, Number, TableOnly };
    Kind kind = Kind::Text;
    Box box;              // the text's box (Text and Number)
    bool leader = false;  // a line from the point to the box
};

struct LabelStyle {
    double charWidth = 6.6;  // a monospace font's advance (0.6 em of 11 px)
    double lineHeight = 13.0;
    double padding = 2.0;  // around the text, inside its box
    double markerRadius = 5.0;
};

// The box a text of `characters` characters takes in `style`.
Box textBox(size_t characters, const LabelStyle& style);

// Places `labels[i]` near `points[i]` (pixels) within `area`. Returns one placement per label.
std::vector<PlacedLabel> placeLabels(const std::vector<std::pair<double, double>>& points,
                                     const std::vector<std::string>& labels, const Box& area,
                                     const LabelStyle& style);

}  // namespace report
