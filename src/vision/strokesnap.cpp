// Snapping a freehand stroke to the photo's edge near it: the stroke says where to look, the edge
// says where the curve goes (docs/vision.md, "Outlines").
#include "vision/outline.h"

#include "geometry/strokefit.h"
#include "vision/edges.h"
#include "vision/pixels.h"

#include <algorithm>
#include <cmath>

namespace kontur::vision {

using geo::Point;

namespace {

// The stroke resampled at even arc-length steps.
std::vector<Point> resample(std::span<const Point> stroke, double step)
{
    std::vector<Point> out{stroke.front()};
    double carry = 0.0;
    for (std::size_t i = 1; i < stroke.size(); ++i) {
        const Point a = stroke[i - 1], b = stroke[i];
        const double len = (b - a).norm();
        double t = step - carry;
        for (; t <= len; t += step)
            out.push_back(a + (b - a) * (t / len));
        carry = len - (t - step);
    }
    if ((out.back() - stroke.back()).norm() > 0.25 * step)
        out.push_back(stroke.back());
    return out;
}

double median(std::vector<double> v)
{
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
}

} // namespace

geo::Result<Outline> snapStrokeToEdges(const cv::Mat &image, const PixelMapping &mapping,
                                       std::span<const Point> strokeMm, double searchRadiusMm,
                                       const OutlineOptions &options)
{
    if (image.empty() || image.rows < 8 || image.cols < 8)
        return geo::Error{geo::ErrorCode::InvalidArgument, "the image is empty"};
    if (!mapping.valid())
        return geo::Error{geo::ErrorCode::InvalidArgument, "the pixel-to-mm map is not invertible"};
    if (!(searchRadiusMm > 0.0) || !std::isfinite(searchRadiusMm) || !(options.tolerance > 0.0))
        return geo::Error{geo::ErrorCode::InvalidArgument, "the search radius and tolerance must be positive"};
    if (strokeMm.size() < 2)
        return geo::Error{geo::ErrorCode::TooFewPoints, "a stroke needs at least 2 points"};
    for (const auto &p : strokeMm)
        if (!p.allFinite())
            return geo::Error{geo::ErrorCode::NonFiniteInput, "a stroke point is not finite"};

    // Work in pixels; one sample per pixel of stroke.
    std::vector<Point> px;
    px.reserve(strokeMm.size());
    for (const auto &p : strokeMm)
        px.push_back(mapping.toPixel(p));
    const std::vector<Point> samples = resample(px, 1.0);
    if (samples.size() < 4)
        return geo::Error{geo::ErrorCode::TooFewPoints, "the stroke is shorter than a few pixels"};
    const double mmpp = mapping.mmPerPixel();
    const double radius = searchRadiusMm / mmpp;
    const cv::Mat gray = toGray(image);
    if (gray.empty())
        return geo::Error{geo::ErrorCode::InvalidArgument, "the image is not 8-bit gray, BGR or BGRA"};
    const detail::EdgeField field = detail::edgeField(gray, 1.0);

    // The normal from the stroke's direction over about a millimetre each way, which hand jitter
    // does not turn much.
    const auto n = static_cast<int>(samples.size());
    const int reach = std::max(2, static_cast<int>(std::lround(1.0 / mmpp)));
    std::vector<Point> normal(samples.size());
    for (int i = 0; i < n; ++i) {
        const Point d = samples[static_cast<std::size_t>(std::min(n - 1, i + reach))] -
                        samples[static_cast<std::size_t>(std::max(0, i - reach))];
        normal[static_cast<std::size_t>(i)] = Point(-d.y(), d.x()).normalized();
    }
    // Which way the edge steps (dark to light along the normal, or the reverse) is the stroke's
    // choice by majority: the stronger of the two over the whole stroke.
    std::vector<std::optional<detail::EdgeHit>> hits[2];
    double total[2] = {0.0, 0.0};
    for (int s = 0; s < 2; ++s)
        for (int i = 0; i < n; ++i) {
            const auto k = static_cast<std::size_t>(i);
            hits[s].push_back(detail::edgeAlong(field, samples[k], normal[k], radius, s == 0 ? 1 : -1, false));
            if (hits[s].back())
                total[s] += std::max(0.0, hits[s].back()->strength);
        }
    const auto &chosen = hits[total[0] >= total[1] ? 0 : 1];

    std::vector<double> strengths;
    for (const auto &h : chosen)
        if (h)
            strengths.push_back(h->strength);
    if (static_cast<int>(strengths.size()) < n / 2)
        return geo::Error{geo::ErrorCode::TooFewPoints, "no edge along most of the stroke"};
    const double floor = median(strengths) / 3.0;

    // Outliers: a weak edge, or an edge point that leaves the run of its neighbours' offsets (a
    // stroke that passes a mark beside the edge).
    const int half = std::max(3, reach);
    std::vector<Point> edge;
    for (int i = 0; i < n; ++i) {
        const auto &h = chosen[static_cast<std::size_t>(i)];
        if (!h || h->strength < floor)
            continue;
        std::vector<double> around;
        for (int j = std::max(0, i - half); j <= std::min(n - 1, i + half); ++j)
            if (const auto &o = chosen[static_cast<std::size_t>(j)]; o && o->strength >= floor)
                around.push_back(o->t);
        if (std::abs(h->t - median(around)) > std::max(2.0, 0.3 / mmpp))
            continue;
        edge.push_back(mapping.toMm(samples[static_cast<std::size_t>(i)] + h->t * normal[static_cast<std::size_t>(i)]));
    }
    if (static_cast<int>(edge.size()) < n / 2)
        return geo::Error{geo::ErrorCode::TooFewPoints, "no edge along most of the stroke"};

    geo::StrokeFitOptions fitOptions;
    fitOptions.tolerance = options.tolerance;
    fitOptions.cornerAngle = options.cornerAngle;
    fitOptions.cornerWindow = std::max(6.0 * mmpp, 0.6);
    auto fit = geo::fitStroke(edge, fitOptions);
    if (!fit)
        return fit.error();
    Outline out;
    out.control = std::move(fit->control);
    out.corner = std::move(fit->corner);
    out.closed = false;
    out.maxError = fit->maxError;
    out.edgePoints = static_cast<int>(edge.size());
    detail::markStraightSegments(out, 0.5 * options.tolerance);
    return out;
}

} // namespace kontur::vision
