#include <report/LabelPlacement.h>

#include <cmath>
#include <numbers>

namespace report {

namespace {

// Rings of candidate spots, nearest first: a label beside its marker, then further out with a leader line.
constexpr double kRings[] = {0.0, 18.0, 36.0, 60.0, 90.0, 130.0, 180.0};
constexpr int kDirections = 16;

bool fits(const Box& box, const Box& area, const std::vector<Box>& taken) {
    if (box.x < area.x || box.y < area.y || box.x + box.width > area.x + area.width ||
        box.y + box.height > area.y + area.height)
        return false;
    for (const Box& other : taken)
        if (box.overlaps(other)) return false;
    return true;
}

// The first free spot for a box of `size` around `point`; false if there is none.
bool findSpot(std::pair<double, double> point, const Box& size, const Box& area,
              const std::vector<Box>& taken, const LabelStyle& style, Box& spot, bool& leader) {
    const double gap = style.markerRadius + 2.0;
    for (double ring : kRings) {
        // The first ring: the four corners beside the marker (upper right first, as labels usually sit).
        if (ring == 0.0) {
            const double left = point.first - gap - size.width, right = point.first + gap;
            const double above = point.second - gap - size.height, below = point.second + gap;
            for (const auto& [x, y] : {std::pair{right, above}, std::pair{right, below},
                                       std::pair{left, above}, std::pair{left, below}}) {
                const Box box{x, y, size.width, size.height};
                if (fits(box, area, taken)) {
                    spot = box;
                    leader = false;
                    return true;
                }
            }
            continue;
        }
        for (int d = 0; d < kDirections; ++d) {
            // Upper right first, then round the circle.
            const double angle = std::numbers::pi / 4.0 - 2.0 * std::numbers::pi * d / kDirections;
            const double cx = point.first + (gap + ring) * std::cos(angle);
            const double cy = point.second - (gap + ring) * std::sin(angle);
            // The box's corner nearest the point sits on the ring.
            const Box box{std::cos(angle) >= 0 ? cx : cx - size.width,
                          std::sin(angle) >= 0 ? cy - size.height : cy, size.width, size.height};
            if (fits(box, area, taken)) {
                spot = box;
                leader = true;
                return true;
            }
        }
    }
    return false;
}

}  // namespace

Box textBox(size_t characters, const LabelStyle& style) {
    return Box{0.0, 0.0, static_cast<double>(characters) * style.charWidth + 2.0 * style.padding,
               style.lineHeight + 2.0 * style.padding};
}

std::vector<PlacedLabel> placeLabels(const std::vector<std::pair<double, double>>& points,
                                     const std::vector<std::string>& labels, const Box& area,
                                     const LabelStyle& style) {
    // Every marker is taken before any label is placed: a label may not hide a point placed after it.
    std::vector<Box> taken;
    for (const auto& [x, y] : points)
        taken.push_back(Box{x - style.markerRadius, y - style.markerRadius, 2.0 * style.markerRadius,
                            2.0 * style.markerRadius});
    std::vector<PlacedLabel> placed(labels.size());
    for (size_t i = 0; i < labels.size() && i < points.size(); ++i) {
        PlacedLabel& label = placed[i];
        if (findSpot(points[i], textBox(labels[i].size(), style), area, taken, style, label.box,
                     label.leader)) {
            label.kind = PlacedLabel::Kind::Text;
        } else if (findSpot(points[i], textBox(std::to_string(i + 1).size(), style), area, taken, style,
                            label.box, label.leader)) {
            label.kind = PlacedLabel::Kind::Number;
        } else {
            label.kind = PlacedLabel::Kind::TableOnly;
            continue;
        }
        taken.push_back(label.box);
    }
    return placed;
}

}  // namespace report
