// The seams of a piece's outline (see seams.h).
#include "geometry/seams.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kontur::geo {

std::vector<SeamSpan> seamSpans(const PiecewiseBezier &outline)
{
    const int n = outline.segmentCount();
    if (n == 0)
        return {};
    if (!outline.isClosed())
        return {{0, n}};
    const double limit = kSeamCornerDegrees * std::numbers::pi / 180.0;
    std::vector<int> corners; // joint j: where segment j starts
    for (const JointContinuity &joint : outline.continuity())
        if (joint.angle > limit)
            corners.push_back(joint.right);
    if (corners.empty())
        return {{0, n}};
    std::sort(corners.begin(), corners.end());
    std::vector<SeamSpan> out;
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const int next = k + 1 < corners.size() ? corners[k + 1] : corners.front() + n;
        out.push_back({corners[k], next - corners[k]});
    }
    return out;
}

int seamOfSegment(const std::vector<SeamSpan> &seams, int segmentCount, int segment)
{
    if (segment < 0 || segment >= segmentCount)
        return -1;
    for (std::size_t k = 0; k < seams.size(); ++k) {
        const int offset = ((segment - seams[k].first) % segmentCount + segmentCount) % segmentCount;
        if (offset < seams[k].count)
            return static_cast<int>(k);
    }
    return -1;
}

std::vector<double> segmentDistancesOf(const PiecewiseBezier &outline, const std::vector<std::optional<double>> &widths,
                                       double fallback)
{
    return segmentDistancesOf(outline.segmentCount(), seamSpans(outline), widths, fallback);
}

std::vector<double> segmentDistancesOf(int n, const std::vector<SeamSpan> &seams,
                                       const std::vector<std::optional<double>> &widths, double fallback)
{
    std::vector<double> out(static_cast<std::size_t>(n), fallback);
    for (std::size_t k = 0; k < seams.size() && k < widths.size(); ++k) {
        if (!widths[k])
            continue;
        for (int i = 0; i < seams[k].count; ++i)
            out[static_cast<std::size_t>((seams[k].first + i) % n)] = *widths[k];
    }
    return out;
}

std::vector<bool> segmentHemsOf(const PiecewiseBezier &outline, const std::vector<int> &hemSeams)
{
    return segmentHemsOf(outline.segmentCount(), seamSpans(outline), hemSeams);
}

std::vector<bool> segmentHemsOf(int n, const std::vector<SeamSpan> &seams, const std::vector<int> &hemSeams)
{
    std::vector<bool> out(static_cast<std::size_t>(n), false);
    for (int k : hemSeams) {
        if (k < 0 || static_cast<std::size_t>(k) >= seams.size())
            continue;
        const SeamSpan &s = seams[static_cast<std::size_t>(k)];
        for (int i = 0; i < s.count; ++i)
            out[static_cast<std::size_t>((s.first + i) % n)] = true;
    }
    return out;
}

} // namespace kontur::geo
